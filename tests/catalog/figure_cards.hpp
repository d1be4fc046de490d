// The catalog tests' figure fixtures: a four-bar mechanism file whose card carries the figures
// given, and the outcome of one named check of an entry's report.
#pragma once

#include "koppel/catalog/check.hpp"
#include "koppel/core/angles.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace koppel::test {

// A four-bar A0 = (0, 0), B0 = (l4, 0), crank l1 driven at A0, coupler l2, rocker l3, B above
// the frame line at the assembly input; the card carries `figures` (YAML list items).
inline std::string FourBar(double l1, double l2, double l3, double l4, double assembly_input, const std::string& figures) {
  const double phi = DegToRad(assembly_input);
  const double ax = l1 * std::cos(phi), ay = l1 * std::sin(phi);
  // B = intersection of circle(A, l2) and circle(B0, l3) with B left of A -> B0 (above for A on the frame line)
  const double dx = l4 - ax, dy = -ay, d = std::hypot(dx, dy);
  const double a = (l2 * l2 - l3 * l3 + d * d) / (2 * d), h = std::sqrt(std::max(0.0, l2 * l2 - a * a));
  const double bx = ax + a * dx / d - h * dy / d, by = ay + a * dy / d + h * dx / d;
  char buffer[2048];
  std::snprintf(buffer, sizeof buffer, R"(name: four-bar
parameters: {l1: %.17g, l2: %.17g, l3: %.17g, l4: %.17g}
links:
  frame: {frame: true, points: {A0: [0, 0], B0: [l4, 0]}}
  crank: {points: {A0: [0, 0], A: [l1, 0]}}
  coupler: {points: {A: [0, 0], B: [l2, 0]}}
  rocker: {points: {B0: [0, 0], B: [l3, 0]}}
joints:
  A0: {type: R, links: [frame, crank]}
  A: {type: R, links: [crank, coupler]}
  B: {type: R, links: [coupler, rocker]}
  B0: {type: R, links: [frame, rocker]}
drive: {joint: A0}
outputs:
  psi: {link: rocker}
  A: {point: crank.A}
assembly: {input: %.17g, points: {B: [%.17g, %.17g]}}
catalog:
  title: {de: Gelenkviereck, en: four-bar}
  kind: transfer
  outputs: [psi]
  features: {drive_joints: 1, output_links: 1, links: 4, joints: 4}
  sweep: {from: 0, to: 360, step: 1}
  figures:
)",
                l1, l2, l3, l4, assembly_input, bx, by);
  return buffer + figures;
}

inline const CheckOutcome& FindOutcome(const EntryReport& r, const std::string& name) {
  for (const CheckOutcome& c : r.checks) {
    if (c.name == name) return c;
  }
  FAIL("no check " << name);
  throw std::logic_error("unreachable");
}

}  // namespace koppel::test
