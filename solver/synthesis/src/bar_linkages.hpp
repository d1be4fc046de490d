// The two linkages most syntheses return, built by name: straight bars along their body x axes,
// the drive at the crank's frame pivot A0, and the outputs a designer reads (the rocker angle
// psi or the slider displacement s, and the transmission angle mu at B). Private to synthesis.
#pragma once

#include "koppel/core/build.hpp"

#include <Eigen/Core>

#include <string>

namespace koppel {

// Four-bar A0-A-B-B0: frame points A0, B0 (global); crank A0 -> A of length `crank`, coupler
// A -> B of `coupler`, rocker B0 -> B of `rocker` (signed lengths turn a body axis round).
inline Mechanism BarFourBar(const std::string& name, const Eigen::Vector2d& a0, const Eigen::Vector2d& b0, double crank,
                            double coupler, double rocker) {
  Mechanism m;
  m.name = name;
  AddLink(m, "frame", {{"A0", a0}, {"B0", b0}}, true);
  AddLink(m, "crank", {{"A0", {0, 0}}, {"A", {crank, 0}}});
  AddLink(m, "coupler", {{"A", {0, 0}}, {"B", {coupler, 0}}});
  AddLink(m, "rocker", {{"B0", {0, 0}}, {"B", {rocker, 0}}});
  Revolute(m, "A0", "frame", "crank");
  Revolute(m, "A", "crank", "coupler");
  Revolute(m, "B", "coupler", "rocker");
  Revolute(m, "B0", "frame", "rocker");
  SetDrive(m, "A0");
  LinkAngleOutput(m, "psi", "rocker");
  TransmissionOutput(m, "mu", "coupler", "B");
  return m;
}

// Slider-crank: frame points A0 and F (global; the slide is the x-parallel line through F),
// crank A0 -> A with A at `crank_a` in the crank's body frame, coupler A -> B of `coupler`,
// slider B on the line; output s = x of B minus x of F.
inline Mechanism BarSliderCrank(const std::string& name, const Eigen::Vector2d& a0, const Eigen::Vector2d& f,
                                const Eigen::Vector2d& crank_a, double coupler) {
  Mechanism m;
  m.name = name;
  AddLink(m, "frame", {{"A0", a0}, {"F", f}}, true);
  AddLink(m, "crank", {{"A0", {0, 0}}, {"A", crank_a}});
  AddLink(m, "coupler", {{"A", {0, 0}}, {"B", {coupler, 0}}});
  AddLink(m, "slider", {{"B", {0, 0}}});
  Revolute(m, "A0", "frame", "crank");
  Revolute(m, "A", "crank", "coupler");
  Revolute(m, "B", "coupler", "slider");
  Prismatic(m, "S", "frame", "F", "slider", "B", Eigen::Vector2d::UnitX());
  SetDrive(m, "A0");
  JointOutput(m, "s", "S");
  TransmissionOutput(m, "mu", "coupler", "B");
  return m;
}

}  // namespace koppel
