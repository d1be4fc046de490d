#include "koppel/core/transmission.hpp"

namespace koppel {

Expected<TransmissionGeometry> ResolveTransmission(const Mechanism& m, const Output& o) {
  using Result = Expected<TransmissionGeometry>;
  TransmissionGeometry g;
  const int coupler = o.link;
  const Joint& out = m.joints[o.joint];
  if (out.link_a != coupler && out.link_b != coupler) {
    return Result::Error("joint '" + out.name + "' does not belong to coupler '" + m.links[coupler].name + "'");
  }
  const int other = OtherJointOfBinaryLink(m, coupler, o.joint);
  if (other < 0) {
    return Result::Error("coupler '" + m.links[coupler].name + "' must be a binary link (exactly two joints)");
  }
  // The coupler carries force along the line between its two joints; for a P joint at the far
  // end that line is not defined by points alone, so both joints must be revolute.
  if (m.joints[other].type != JointType::kRevolute || out.type != JointType::kRevolute) {
    return Result::Error("the coupler's joints '" + m.joints[other].name + "' and '" + out.name + "' must be revolute");
  }
  g.coupler_from = JointPointOn(m.joints[other], coupler);
  g.coupler_to = JointPointOn(out, coupler);
  const int output_link = out.link_a == coupler ? out.link_b : out.link_a;
  const int frame = m.FrameLink();
  for (int k = 0; k < static_cast<int>(m.joints.size()); ++k) {
    const Joint& j = m.joints[k];
    if (k == o.joint) continue;
    const bool joins_frame = (j.link_a == frame && j.link_b == output_link) || (j.link_b == frame && j.link_a == output_link);
    if (!joins_frame) continue;
    if (j.type == JointType::kRevolute) {
      g.pivot = JointPointOn(j, output_link);
      return g;
    }
    if (j.link_a == frame) {  // the slide line belongs to the frame: its direction is fixed
      g.slide_joint = k;
      return g;
    }
  }
  return Result::Error("output link '" + m.links[output_link].name + "' must turn about or slide on the frame");
}

}  // namespace koppel
