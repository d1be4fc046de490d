// Independent references for the instantaneous geometry of plane motion (curvature_test,
// instant_centres_test). Global frame, lengths.
#pragma once

#include <Eigen/Core>

#include <optional>

namespace koppel::test {

// The intersection of the line through p1, p2 with the line through q1, q2 (none when parallel):
// for a four-bar the coupler's pole is where the crank line A0A meets the rocker line B0B
// (Aronhold–Kennedy; seed 003, "Im Schnittpunkt der Schwingengeraden A0'A' mit B0'B' befindet
// sich der Geschwindigkeitspol P").
std::optional<Eigen::Vector2d> LineIntersection(const Eigen::Vector2d& p1, const Eigen::Vector2d& p2, const Eigen::Vector2d& q1,
                                                const Eigen::Vector2d& q2);

// The centre of curvature K0 of the path of point K by the Euler–Savary equation (seed 003:
// "Mit Hilfe der Euler-Savaryschen-Formel ... als Krümmungsmittelpunkte"), in the form
// 1/PK - 1/PK0 = 1/PW_K with signed distances along the pole ray from the pole P through K, W_K
// the ray's second intersection with the inflection circle (diameter PW, W the inflection pole).
// None when K lies on the inflection circle (K0 at infinity). Check: a wheel of radius R rolling on
// a line has W at its hub; its top point (PK = 2R, PW_K = R) gets PK0 = -2R, rho = 4R, the
// cycloid's radius at its crest.
std::optional<Eigen::Vector2d> EulerSavaryCentre(const Eigen::Vector2d& pole, const Eigen::Vector2d& inflection_pole, const Eigen::Vector2d& k);

// The signed curvature of a plane path from its first and second derivatives by any parameter:
// (x' y'' - y' x'') / (x'^2 + y'^2)^(3/2).
double PathCurvature(double x1, double y1, double x2, double y2);

}  // namespace koppel::test
