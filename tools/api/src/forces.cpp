#include "koppel/api/forces.hpp"

#include "display.hpp"
#include "model_impl.hpp"

#include "koppel/analysis/forces.hpp"
#include "koppel/core/angles.hpp"

#include <functional>

namespace koppel {
namespace {

ForcesOptions ForcesOptionsOf(const Model& model, const ForcesRequest& request) {
  const Mechanism& m = model.mechanism();
  const SweepSpan span = model.Span(request.from, request.to, request.step);
  ForcesOptions options;
  options.sweep.from = api_detail::InputInternal(m, span.from);
  options.sweep.to = api_detail::InputInternal(m, span.to);
  options.sweep.step = api_detail::InputInternal(m, span.step);
  options.sweep.continuation.at_branch_point = request.at_branch_point;
  if (request.speed) options.speed = m.InputIsAngle() ? *request.speed * 2.0 * kPi / 60.0 : *request.speed;  // rpm -> rad/s
  return options;
}

// One column of the table: its name, unit and how to read it off a row (empty when the row
// does not have it).
struct ForcesColumn {
  std::string name, unit;
  std::function<std::optional<double>(const ForcesRow&)> value;
};

// The rows' values known only where the reactions were computed, or where virtual work was.
template <class Get>
auto WhereComputed(Get get) {
  return [get](const ForcesRow& r) -> std::optional<double> { return r.computed ? std::optional<double>(get(r)) : std::nullopt; };
}
template <class Get>
auto WhereVirtualWork(Get get) {
  return [get](const ForcesRow& r) -> std::optional<double> { return r.virtual_work ? std::optional<double>(get(r)) : std::nullopt; };
}

void AddJointColumns(const Mechanism& m, std::vector<ForcesColumn>& columns) {
  for (size_t j = 0; j < m.joints.size(); ++j) {
    const std::string& name = m.joints[j].name;
    columns.push_back({ComponentName(name, 0), "N", WhereComputed([j](const ForcesRow& r) { return r.joints[j].force.x(); })});
    columns.push_back({ComponentName(name, 1), "N", WhereComputed([j](const ForcesRow& r) { return r.joints[j].force.y(); })});
    if (m.joints[j].type == JointType::kPrismatic) {
      columns.push_back({name + "_N", "N", WhereComputed([j](const ForcesRow& r) { return r.joints[j].normal; })});
      columns.push_back({name + "_M", "N m", WhereComputed([j](const ForcesRow& r) { return r.joints[j].moment; })});
    }
  }
}

std::vector<ForcesColumn> ForcesLayout(const Mechanism& m) {
  const bool angle = m.InputIsAngle();
  const std::string drive = angle ? "torque" : "force", drive_unit = angle ? "N m" : "N";
  const std::string inertia = angle ? "J_red" : "m_red";
  std::vector<ForcesColumn> columns;
  columns.push_back({m.drive.input_name, angle ? "deg" : "length",
                     [&m](const ForcesRow& r) { return std::optional<double>(api_detail::InputShown(m, r.input)); }});
  columns.push_back({drive, drive_unit, WhereComputed([](const ForcesRow& r) { return r.drive; })});
  columns.push_back({drive + "_vw", drive_unit, WhereVirtualWork([](const ForcesRow& r) { return r.drive_virtual_work; })});
  columns.push_back({inertia, angle ? "kg m^2" : "kg", WhereVirtualWork([](const ForcesRow& r) { return r.reduced_inertia; })});
  columns.push_back({inertia + "_d1", angle ? "kg m^2/rad" : "kg/m",
                     WhereVirtualWork([](const ForcesRow& r) { return r.reduced_inertia_derivative; })});
  AddJointColumns(m, columns);
  columns.push_back({"singular", "1", [](const ForcesRow& r) { return std::optional<double>(r.singular ? 1.0 : 0.0); }});
  return columns;
}

}  // namespace

bool ForcesRequest::IsValid(const Model& model, std::string* why) const { return ForcesOptionsOf(model, *this).IsValid(why); }

ForcesTable AnalyseForces(const Model& model, const ForcesRequest& request) {
  const Mechanism& m = model.mechanism();
  const ForcesOptions options = ForcesOptionsOf(model, request);
  if (std::string why; !options.IsValid(&why)) api_detail::BadInput(model.path(), "from/to/step/speed", why);
  const Loads& loads = model.loads();
  ForcesTable table;
  if (!loads.HasMass() && loads.forces.empty() && loads.torques.empty() && loads.springs.empty())
    table.notes.push_back("note: the file gives no masses and no loads, so every force is zero (README.md, 'Masses and loads')");
  const ForcesResult result = AnalyseForces(m, loads, options);
  table.status = result.status;
  table.message = result.message;
  table.bad_input = result.bad_input;
  table.kinetostatic = result.kinetostatic;
  table.worst_disagreement = result.worst_disagreement;
  table.sweep = api_detail::Shown(m, result.sweep);
  const std::vector<ForcesColumn> columns = ForcesLayout(m);
  for (const ForcesColumn& c : columns) {
    table.columns.push_back(c.name);
    table.units.push_back(c.unit);
  }
  for (const ForcesRow& row : result.rows) {
    std::vector<std::optional<double>>& cells = table.rows.emplace_back();
    for (const ForcesColumn& c : columns) cells.push_back(c.value(row));
  }
  return table;
}

}  // namespace koppel
