// Which parameters of a mechanism file make its mechanism: a parameter that no formula reads
// changes nothing when set, so setting it (--set, Model::With, a fit's free parameter) is an
// error rather than a silent no-op.
#pragma once

#include "koppel/catalog/mechanism_file.hpp"

#include <string>
#include <vector>

namespace koppel {

// The parameters, in file order, named by a formula of the model part (links, joints, drive,
// outputs, assembly, sweep, units, masses, loads' magnitudes) directly or through the formulas
// of other parameters that are read. The catalog card's formulas do not count: they check the
// mechanism, they do not make it.
std::vector<std::string> ParametersRead(const MechanismFile& file);

// What a parameter's value measures, read off the places its value goes: kLength when every
// formula that reads it (directly or through parameters) is a coordinate of a point (links'
// points and centres of gravity, assembly points) or a slide's input (a P drive's zero, assembly
// input, sweep), kAngle when every one is an angle in degrees (a P joint's angle, an R drive's
// zero, assembly input and sweep, an output's zero); and only where it enters each formula on the
// way as a term or factor: outside every function's brackets, not after '/' or '^' nor before
// '^' (c2 in `c2*cos(gamma*deg)` is a length, gamma is neither). Otherwise kUnknown.
enum class ParameterMeasure { kLength, kAngle, kUnknown };
ParameterMeasure MeasureOf(const MechanismFile& file, const std::string& name);

// The message for setting `name`, a parameter that ParametersRead does not list: it names the
// parameter and the ones that are read.
std::string UnreadParameterMessage(const std::string& name, const std::vector<std::string>& read);

}  // namespace koppel
