// koppel._koppel: the library API (koppel/koppel.hpp) for Python. Names follow Python's habits
// (snake_case); units, frames and failure behaviour are those of koppel/api/model.hpp: inputs in
// degrees (R drive) or length (P drive), angle outputs in degrees, transfer functions per radian.
// koppel::InputError becomes koppel.InputError (a ValueError) with file, line, column, field and
// every diagnostic; statuses are strings ("complete", "partial", "failed", "ok", ...).
#include <koppel/koppel.hpp>

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <tuple>

namespace py = pybind11;
using namespace koppel;

namespace {

// {"e": 0.8, "l1": "l2/2"} -> overrides; numbers with 17 digits, strings as formulas
ParameterValues Overrides(const std::optional<py::dict>& set) {
  ParameterValues values;
  if (!set) return values;
  for (const auto& [key, value] : *set) {
    const std::string name = py::str(key);
    if (py::isinstance<py::str>(value)) {
      values.emplace_back(name, value.cast<std::string>());
    } else {
      values.emplace_back(name, py::str(py::repr(py::float_(value.cast<double>()))).cast<std::string>());
    }
  }
  return values;
}

py::array_t<double> Matrix(const SweepTable& t) {
  py::array_t<double> a({static_cast<py::ssize_t>(t.rows), static_cast<py::ssize_t>(t.columns.size())});
  std::copy(t.values.begin(), t.values.end(), a.mutable_data());
  return a;
}

py::array_t<double> Vector(const std::vector<double>& v) {
  py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

py::dict SingularDict(const SingularPosition& p) {
  py::dict d;
  d["kind"] = p.kind;
  d["input"] = p.input;
  d["rcond"] = p.rcond;
  d["joints"] = p.joints;
  d["action"] = p.action;
  return d;
}
py::list SingularList(const std::vector<SingularPosition>& points) {
  py::list l;
  for (const SingularPosition& p : points) l.append(SingularDict(p));
  return l;
}
py::list GapList(const std::vector<InputGap>& gaps) {
  py::list l;
  for (const InputGap& g : gaps) l.append(py::make_tuple(g.from, g.to));
  return l;
}

// {at, input, value}, or None when the extremes were not found
py::object ExtremeDict(bool found, const OutputExtremePoint& e) {
  if (!found) return py::none();
  py::dict d;
  d["at"] = e.at;
  d["input"] = e.input;
  d["value"] = e.value;
  return d;
}

py::dict Figures(const Design& d) {
  py::dict f;
  for (const DesignFigure& figure : d.figures) f[py::str(figure.name)] = figure.value;
  return f;
}

py::object Optional(const std::optional<double>& v) { return v ? py::object(py::float_(*v)) : py::none(); }

// {name: value or None} in the order koppel curvature prints them, plus what the report says
py::dict CurvatureDict(const CurvatureReport& r) {
  py::dict d;
  d["status"] = ToString(r.status);
  d["message"] = r.message;
  d["point"] = r.point;
  d["link"] = r.link;
  for (const NamedValue& v : r.Quantities()) d[py::str(v.name)] = Optional(v.value);
  d["rho_infinite"] = r.curvature.has_value() && *r.curvature == 0.0;
  return d;
}

py::dict PolesDict(const PolesReport& r) {
  py::dict d;
  d["status"] = ToString(r.status);
  d["message"] = r.message;
  d["input"] = r.input;
  py::list poles;
  for (const InstantCentreEntry& c : r.centres) {
    py::dict e;
    e["link_a"] = c.link_a;
    e["link_b"] = c.link_b;
    e["kind"] = !c.defined ? "undefined" : c.at_infinity ? "infinity" : c.from_acceleration ? "acceleration" : "finite";
    const bool finite = c.defined && !c.at_infinity;
    e["pole"] = finite ? py::object(py::make_tuple(c.position.x, c.position.y)) : py::none();
    e["direction"] = c.at_infinity ? py::object(py::make_tuple(c.direction.x, c.direction.y)) : py::none();
    poles.append(e);
  }
  d["poles"] = poles;
  return d;
}

// a curve as an (n, 2) array with NaN where the pole is at infinity
py::array_t<double> Curve(const std::vector<std::optional<Point2>>& points) {
  py::array_t<double> a({static_cast<py::ssize_t>(points.size()), static_cast<py::ssize_t>(2)});
  double* out = a.mutable_data();
  for (size_t i = 0; i < points.size(); ++i) {
    out[2 * i] = points[i] ? points[i]->x : std::nan("");
    out[2 * i + 1] = points[i] ? points[i]->y : std::nan("");
  }
  return a;
}

py::dict ToleranceDict(const ToleranceResult& r) {
  py::dict d;
  d["status"] = ToString(r.status);
  d["message"] = r.message;
  d["output"] = r.output;
  d["unit"] = r.unit;
  d["distribution"] = r.distribution;
  d["samples"] = r.samples;
  d["seed"] = r.seed;
  d["quantile_levels"] = r.quantile_levels;
  const std::vector<std::string> columns = r.Columns();
  py::list rows;
  for (size_t i = 0; i < r.rows.size(); ++i) {
    py::dict row;
    const auto values = r.Row(i);
    for (size_t c = 0; c < columns.size(); ++c) row[py::str(columns[c])] = Optional(values[c]);
    if (!r.rows[i].ok) row["message"] = r.rows[i].message;
    rows.append(row);
  }
  d["rows"] = rows;
  return d;
}

// koppel.SweepTable: a sweep in the layout of `koppel analyze`, as NumPy columns.
void BindSweepTable(py::module_& m) {
  py::class_<SweepTable>(m, "SweepTable",
                         "A sweep of the drive, laid out as `koppel analyze`: the input, then per output y the columns y, "
                         "y_d1 .. y_d<order> (a point K: K_x, K_y, ...), then 'singular'. values is a NumPy array (rows x "
                         "columns); t['s'] one column; t.to_dict() {name: column} for pandas.DataFrame. NaN marks only a "
                         "transfer function above the order a singular pose allows (valid_order per row).")
      .def_property_readonly("status", [](const SweepTable& t) { return ToString(t.status); })
      .def_property_readonly("complete", [](const SweepTable& t) { return t.status == AnalysisStatus::kComplete; })
      .def_readonly("message", &SweepTable::message)
      .def_readonly("notes", &SweepTable::notes)
      .def_readonly("order", &SweepTable::order)
      .def_readonly("columns", &SweepTable::columns)
      .def_readonly("units", &SweepTable::units)
      .def_property_readonly("values", &Matrix)
      .def_property_readonly("valid_order", [](const SweepTable& t) {
        std::vector<double> v(t.valid_order.begin(), t.valid_order.end());
        return Vector(v);
      })
      .def_property_readonly("singular_points", [](const SweepTable& t) { return SingularList(t.singular_points); })
      .def_property_readonly("gaps", [](const SweepTable& t) { return GapList(t.gaps); })
      .def("__getitem__", [](const SweepTable& t, const std::string& name) { return Vector(t.Column(name)); })
      .def("__len__", [](const SweepTable& t) { return t.rows; })
      .def("to_dict", [](const SweepTable& t) {
        py::dict d;
        for (const std::string& name : t.columns) d[py::str(name)] = Vector(t.Column(name));
        return d;
      }, "{column name: NumPy array}, in column order: pandas.DataFrame(t.to_dict())")
      .def("brief", &SweepTable::Brief)
      .def("__repr__", [](const SweepTable& t) { return "<koppel.SweepTable " + t.Brief() + ">"; });
}

// koppel.Pose: one row of the sweep layout at the current input.
void BindPose(py::module_& m) {
  py::class_<PoseResult>(m, "Pose", "One pose: a row of the sweep layout at the current input.")
      .def_property_readonly("status", [](const PoseResult& p) { return ToString(p.status); })
      .def_property_readonly("ok", [](const PoseResult& p) { return p.status == AnalysisStatus::kComplete; })
      .def_readonly("message", &PoseResult::message)
      .def_readonly("input", &PoseResult::input)
      .def_readonly("columns", &PoseResult::columns)
      .def_readonly("valid_order", &PoseResult::valid_order)
      .def_readonly("singular", &PoseResult::singular)
      .def("__getitem__", &PoseResult::Get)
      .def("to_dict", [](const PoseResult& p) {
        py::dict d;
        for (size_t c = 0; c < p.columns.size() && c < p.values.size(); ++c) d[py::str(p.columns[c])] = p.values[c];
        return d;
      })
      .def("brief", &PoseResult::Brief)
      .def("__repr__", [](const PoseResult& p) { return "<koppel.Pose " + p.Brief() + ">"; });
}

// koppel.DeadCentres: the dead centres and extremes of a scalar output.
void BindDeadCentres(py::module_& m) {
  py::class_<DeadCentres>(m, "DeadCentres",
                          "Dead centres of a scalar output (koppel deadcentres): points [{kind, input, value, d2}], and where "
                          "they pair up the stroke, input_a/input_i (extended/folded), value_a/value_i, forward_angle and "
                          "phase_ratio, time_ratio (slow stroke over fast, >= 1); the output's minimum and maximum {at, input, value} (a transmission angle's mu_min "
                          "and mu_max; at: stationary, fold or range end), None when not found (extremes_message).")
      .def_property_readonly("status", [](const DeadCentres& d) { return ToString(d.status); })
      .def_readonly("message", &DeadCentres::message)
      .def_property_readonly("points", [](const DeadCentres& d) {
        py::list l;
        for (const DeadCentrePoint& p : d.points) {
          py::dict e;
          e["kind"] = p.kind;
          e["input"] = p.input;
          e["value"] = p.value;
          e["d2"] = p.second;
          l.append(e);
        }
        return l;
      })
      .def_readonly("has_stroke", &DeadCentres::has_stroke)
      .def_readonly("stroke", &DeadCentres::stroke)
      .def_readonly("input_a", &DeadCentres::input_a)
      .def_readonly("input_i", &DeadCentres::input_i)
      .def_readonly("value_a", &DeadCentres::value_a)
      .def_readonly("value_i", &DeadCentres::value_i)
      .def_readonly("forward_angle", &DeadCentres::forward_angle)
      .def_readonly("phase_ratio", &DeadCentres::phase_ratio)
      .def_readonly("time_ratio", &DeadCentres::time_ratio)
      .def_readonly("has_extremes", &DeadCentres::has_extremes)
      .def_property_readonly("minimum", [](const DeadCentres& d) { return ExtremeDict(d.has_extremes, d.minimum); })
      .def_property_readonly("maximum", [](const DeadCentres& d) { return ExtremeDict(d.has_extremes, d.maximum); })
      .def_readonly("extremes_message", &DeadCentres::extremes_message)
      .def_readonly("unresolved", &DeadCentres::unresolved)
      .def_property_readonly("singular_points", [](const DeadCentres& d) { return SingularList(d.singular_points); })
      .def_property_readonly("gaps", [](const DeadCentres& d) { return GapList(d.gaps); })
      .def("brief", &DeadCentres::Brief)
      .def("__repr__", [](const DeadCentres& d) { return "<koppel.DeadCentres " + d.Brief() + ">"; });
}

// koppel.Ranges: the drivable ranges of the branches.
void BindRanges(py::module_& m) {
  py::class_<Ranges>(m, "Ranges",
                     "Drivable ranges (koppel range): branches [{branch, from, to, from_kind, to_kind, period, "
                     "singular_points, message}]; kinds: limit, branch-point, full-turn, bound, failed.")
      .def_property_readonly("status", [](const Ranges& r) { return ToString(r.status); })
      .def_readonly("message", &Ranges::message)
      .def_readonly("notes", &Ranges::notes)
      .def_property_readonly("branches", [](const Ranges& r) {
        py::list l;
        for (const BranchInterval& b : r.branches) {
          py::dict e;
          e["branch"] = b.branch;
          e["from"] = b.from;
          e["to"] = b.to;
          e["from_kind"] = b.from_kind;
          e["to_kind"] = b.to_kind;
          e["period"] = b.period;
          e["singular_points"] = SingularList(b.singular_points);
          e["message"] = b.message;
          l.append(e);
        }
        return l;
      })
      .def("brief", &Ranges::Brief)
      .def("__repr__", [](const Ranges& r) { return "<koppel.Ranges " + r.Brief() + ">"; });
}

void BindResults(py::module_& m) {
  BindSweepTable(m);
  BindPose(m);
  BindDeadCentres(m);
  BindRanges(m);
}

// The Python Mechanism: an immutable koppel::Model with the Workspace of its pose beside it (the
// workspace keeps the model); set() takes the model with the new value and forgets the pose.
struct PyMechanism {
  explicit PyMechanism(Model model) : pose(std::move(model)) {}
  const Model& model() const { return pose.model(); }
  Workspace pose;
};

// A Model's method as a method of the Python Mechanism.
template <class R>
auto Of(R (Model::*method)() const) {
  return [method](const PyMechanism& self) { return (self.model().*method)(); };
}

py::object Designed(const Design& d) {
  py::dict r;
  r["status"] = ToString(d.status);
  r["ok"] = d.ok();
  r["message"] = d.message;
  r["figures"] = Figures(d);
  r["mechanism"] = d.model ? py::cast(PyMechanism(*d.model)) : py::none();
  return r;
}

// Several designs: {"status", "ok", "message", "designs": [design dicts]}.
py::dict DesignList(const Designs& r) {
  py::dict out;
  out["status"] = ToString(r.status);
  out["ok"] = r.ok();
  out["message"] = r.message;
  py::list designs;
  for (const Design& d : r.designs) designs.append(Designed(d));
  out["designs"] = designs;
  return out;
}

// Mechanism: reading it, its names and parameters.
void BindModelFile(py::class_<PyMechanism>& c) {
  c.def_static("load", [](const std::string& path, std::optional<py::dict> set) { return PyMechanism(Model::Load(path, Overrides(set))); },
                  py::arg("path"), py::kw_only(), py::arg("set") = py::none(),
                  "Reads a mechanism file, or the catalog's entry when path is no file but a catalog id ('crank-rocker');\n"
                  "set={'e': 0.8} overrides parameters (numbers or formulas). Raises koppel.InputError, also for a\n"
                  "mechanism whose mobility is not 1 (one drive), as every koppel command refuses it.")
      .def_static("parse",
                  [](const std::string& text, const std::string& name, std::optional<py::dict> set) {
                    return PyMechanism(Model::Parse(text, name, Overrides(set)));
                  },
                  py::arg("text"), py::arg("name") = "<string>", py::kw_only(), py::arg("set") = py::none(),
                  "The same from the text of a mechanism file; name stands for the file in messages.")
      .def_property_readonly("name", Of(&Model::name))
      .def_property_readonly("title", Of(&Model::title))
      .def_property_readonly("path", Of(&Model::path))
      .def_property_readonly("notes", Of(&Model::notes), "What admitting the mechanism noted (an overconstrained linkage that moves).")
      .def_property_readonly("input_name", Of(&Model::input_name))
      .def_property_readonly("input_is_angle", Of(&Model::input_is_angle))
      .def_property_readonly("outputs", Of(&Model::output_names))
      .def_property_readonly("parameters", [](const PyMechanism& self) {
        py::dict d;
        for (const auto& [name, value] : self.model().parameters()) d[py::str(name)] = value;
        return d;
      }, "{name: value} after evaluation, in file order")
      .def("set", [](PyMechanism& self, const std::string& name, const py::object& value) {
        // the model is immutable: this Mechanism takes the model with the new value (Model::With)
        self.pose = Workspace(py::isinstance<py::str>(value) ? self.model().With(name, value.cast<std::string>())
                                                           : self.model().With(name, value.cast<double>()));
      }, py::arg("name"), py::arg("value"), "Overrides one parameter (number or formula); the pose is forgotten.");
}

// Mechanism: its pose and the sweep of the drive.
void BindModelMotion(py::class_<PyMechanism>& c) {
  c.def("assemble", [](PyMechanism& self, int order) { return self.pose.Assemble(order); }, py::arg("order") = 2, "Assembles at the file's hint: the current pose (a Pose).")
      .def("move_to",
           [](PyMechanism& self, double input, int order, const std::string& at) { return self.pose.MoveTo(input, order, ParseAtBranchPoint(at)); },
           py::arg("input"), py::arg("order") = 2, py::arg("at_branch_point") = "continue",
           "Drives along the branch to `input`; a failed Pose when a limit point lies between (it stays there).")
      .def_property_readonly("assembled", [](const PyMechanism& self) { return self.pose.assembled(); })
      .def("sweep",
           [](const PyMechanism& self, std::optional<double> start, std::optional<double> stop, std::optional<double> step, int order,
              const std::string& at) {
             const SweepSpan span = self.model().Span(start, stop, step);  // the file's sweep for what is not given
             return self.model().Sweep(span.from, span.to, span.step, order, ParseAtBranchPoint(at));
           },
           py::arg("start") = py::none(), py::arg("stop") = py::none(), py::arg("step") = py::none(), py::kw_only(),
           py::arg("order") = 2, py::arg("at_branch_point") = "continue",
           "The table of `koppel analyze` from start to stop by step (default: the file's sweep), transfer functions to "
           "`order` (0..8).");
}

// Mechanism: what is read off it (dead centres, ranges, singular positions, curvature, poles, centrodes).
void BindModelAnalyses(py::class_<PyMechanism>& c) {
  c.def("dead_centres",
           [](const PyMechanism& self, const std::string& output, std::optional<double> start, std::optional<double> stop,
              std::optional<double> step) { return self.model().FindDeadCentres(output, start, stop, step); },
           py::arg("output") = "", py::arg("start") = py::none(), py::arg("stop") = py::none(), py::arg("step") = py::none(),
           "Dead centres of a scalar output (default: the first) over the file's sweep, searched in steps of 1.")
      .def("range",
           [](const PyMechanism& self, bool all_branches, const std::string& at) { return self.model().DrivableRanges(all_branches, ParseAtBranchPoint(at)); },
           py::kw_only(), py::arg("all_branches") = false, py::arg("at_branch_point") = "continue",
           "Drivable ranges of the hint's branch (or of every branch koppel finds).")
      .def("singular_positions", [](const PyMechanism& self) { return SingularList(self.model().SingularPositions()); },
           "Singular positions a sweep over the file's range meets.")
      .def("curvature", [](const PyMechanism& self, const std::string& point, double at) { return CurvatureDict(self.model().Curvature(point, at)); },
           py::arg("point"), py::kw_only(), py::arg("at"),
           "koppel curvature: pole, pole_direction, inflection circle, Ball point, and the point's curvature, rho and centre "
           "at input `at`, as a dict of the CLI's names (None where a quantity does not exist here).")
      .def("poles", [](const PyMechanism& self, double at) { return PolesDict(self.model().Poles(at)); }, py::kw_only(), py::arg("at"),
           "koppel poles: the instant centres of every pair of links at input `at`.")
      .def("centrodes",
           [](const PyMechanism& self, const std::string& link, const std::string& reference, std::optional<double> start,
              std::optional<double> stop, double step, double at) {
             const SweepSpan span = self.model().Span(start, stop, step);
             const CentrodesReport r = self.model().Centrodes(link, reference, span.from, span.to, span.step, at);
             py::dict d;
             d["status"] = ToString(r.status);
             d["message"] = r.message;
             d["inputs"] = Vector(r.inputs);
             d["fixed"] = Curve(r.fixed);
             d["moving"] = Curve(r.moving);
             d["moving_at"] = Curve(r.moving_at);
             return d;
           },
           py::arg("link"), py::kw_only(), py::arg("reference") = "", py::arg("start") = py::none(), py::arg("stop") = py::none(),
           py::arg("step") = 1.0, py::arg("at") = 0.0,
           "The fixed and moving centrodes of `link` against `reference` (default: the frame), (n, 2) arrays; moving_at: the "
           "moving one carried to the pose at `at`.");
}

// Mechanism: tolerances, cognates, its file text.
void BindModelTolerances(py::class_<PyMechanism>& c) {
  c.def("tolerance",
           [](const PyMechanism& self, const std::string& output, const std::vector<double>& inputs, const std::map<std::string, double>& tol,
              const std::map<std::string, double>& clearance, long samples, std::uint64_t seed, const std::string& distribution, int threads) {
             ToleranceRequest request;
             request.output = output;
             request.inputs = inputs;
             request.tolerances.assign(tol.begin(), tol.end());
             request.clearances.assign(clearance.begin(), clearance.end());
             request.samples = samples;
             request.seed = seed;
             request.distribution = distribution;
             request.threads = threads;
             ToleranceResult r;
             {
               py::gil_scoped_release release;
               r = self.model().Tolerances(request);
             }
             return ToleranceDict(r);
           },
           py::arg("output"), py::kw_only(), py::arg("inputs"), py::arg("tol") = std::map<std::string, double>{},
           py::arg("clearance") = std::map<std::string, double>{}, py::arg("samples") = 0, py::arg("seed") = 1,
           py::arg("distribution") = "uniform", py::arg("threads") = 0,
           "koppel tolerance: exact sensitivities, worst case, rss, shares, clearance and a seeded Monte Carlo run of `output` "
           "at each input; rows are dicts with the CLI's column names.")
      .def("_cognates", [](const PyMechanism& self, const std::string& point) { return DesignList(FindCognates(self.model(), point)); })
      .def("to_yaml", Of(&Model::ToYaml),
           "The mechanism as a mechanism file: the file it was read from, the parameters set since changed in place\n"
           "(formulas, comments, units, masses and loads as written).")
      .def("__repr__", [](const PyMechanism& self) { return "<koppel.Mechanism '" + self.model().name() + "' from " + self.model().path() + ">"; });
}

void BindModel(py::module_& m) {
  py::class_<PyMechanism> c(m, "Mechanism",
                      "A mechanism from a mechanism file, with its parameters and a current pose. Inputs in degrees (R drive) "
                      "or length (P drive); angle outputs in degrees; transfer functions per radian of the input.");
  BindModelFile(c);
  BindModelMotion(c);
  BindModelAnalyses(c);
  BindModelTolerances(c);
}

void BindCatalog(py::module_& m) {
  py::class_<CatalogHit>(m, "CatalogEntry", "An entry of the catalog; load() reads it as a Mechanism.")
      .def_readonly("id", &CatalogHit::id)
      .def_readonly("title", &CatalogHit::title_en)
      .def_readonly("title_de", &CatalogHit::title_de)
      .def_readonly("path", &CatalogHit::path)
      .def_readonly("kind", &CatalogHit::kind)
      .def_readonly("classes", &CatalogHit::classes)
      .def_readonly("links", &CatalogHit::links)
      .def_readonly("joints", &CatalogHit::joints)
      .def_readonly("revolute", &CatalogHit::revolute)
      .def_readonly("prismatic", &CatalogHit::prismatic)
      .def("load", [](const CatalogHit& h, std::optional<py::dict> set) { return PyMechanism(h.Load(Overrides(set))); }, py::kw_only(),
           py::arg("set") = py::none())
      .def("__repr__", [](const CatalogHit& h) { return "<koppel.CatalogEntry '" + h.id + "'>"; });
  m.def("_catalog_find", [](const py::dict& counts, const std::string& kind, const std::string& klass, const std::string& motion,
                            const std::string& text, const std::string& directory) {
    CatalogQuery q;
    auto count = [&](const char* key, std::optional<std::string>& field) {
      if (counts.contains(key) && !counts[key].is_none()) field = py::str(counts[key]).cast<std::string>();
    };
    count("links", q.links);
    count("binary", q.binary);
    count("ternary", q.ternary);
    count("quaternary", q.quaternary);
    count("joints", q.joints);
    count("revolute", q.revolute);
    count("prismatic", q.prismatic);
    count("drives", q.drives);
    count("outputs", q.outputs);
    q.kind = kind;
    q.klass = klass;
    q.motion = motion;
    q.text = text;
    return FindInCatalog(q, directory);
  });
  m.def("_catalog_directory", &CatalogDirectory);
}

// The closed-form syntheses: crank-rocker, slider-crank, MzC.
void BindClosedFormSynthesis(py::module_& m) {
  m.def("_crank_rocker", [](double phi0, double psi0, const std::string& rocker_sense, std::optional<double> beta,
                            std::optional<double> lambda, double frame, const std::string& sense) {
    CrankRockerSpec s;
    s.phi0 = phi0;
    s.psi0 = psi0;
    if (rocker_sense != "same" && rocker_sense != "opposite")
      throw InputError({Diagnostic{"synthesis request", 0, 0, "rocker_sense", "expected same or opposite, found '" + rocker_sense + "'"}});
    if (sense != "ccw" && sense != "cw")
      throw InputError({Diagnostic{"synthesis request", 0, 0, "sense", "expected ccw or cw, found '" + sense + "'"}});
    s.same_sense = rocker_sense == "same";
    s.beta = beta;
    s.lambda = lambda;
    s.frame = frame;
    s.clockwise = sense == "cw";
    return Designed(SynthesiseCrankRocker(s));
  });
  m.def("_slider_crank", [](double phi0, double stroke, std::optional<double> offset, std::optional<double> beta) {
    SliderCrankSpec s;
    s.phi0 = phi0;
    s.stroke = stroke;
    s.offset = offset;
    s.beta = beta;
    return Designed(SynthesiseSliderCrank(s));
  });
  m.def("_mzc", [](std::optional<double> lambda, std::optional<double> kappa, double diameter) {
    MzcSpec s;
    s.lambda = lambda;
    s.kappa = kappa;
    s.diameter = diameter;
    return Designed(SynthesiseMzc(s));
  });
}

// The numerical syntheses: function generators, fits, motion (Burmester) four-bars.
void BindNumericalSynthesis(py::module_& m) {
  m.def("_function", [](const std::function<double(double)>& f, const std::string& type, double x_from, double x_to, double in_from,
                        double in_to, double out_from, double out_to, int points, const std::vector<double>& at, double frame) {
    FunctionSpec s;
    s.f = f;
    s.type = type;
    s.x_from = x_from;
    s.x_to = x_to;
    s.input_from = in_from;
    s.input_to = in_to;
    s.output_from = out_from;
    s.output_to = out_to;
    s.points = points;
    s.at = at;
    s.frame = frame;
    return Designed(SynthesiseFunction(s));
  });
  m.def("_fit", [](const std::string& problem, int threads) {
    FitSpec s;
    s.problem = problem;
    s.threads = threads;
    Design d;
    {
      py::gil_scoped_release unlocked;  // the starts run on threads of their own and call no Python
      d = SynthesiseFit(s);
    }
    return Designed(d);
  });
  m.def("_motion", [](const std::vector<std::tuple<double, double, double>>& poses, const std::vector<std::pair<double, double>>& circle_points,
                      double crank_turn, int curve_samples, bool require_crank, int threads) {
    MotionSpec s;
    for (const auto& [x, y, angle] : poses) s.poses.push_back({x, y, angle});
    s.circle_points = circle_points;
    s.crank_turn = crank_turn;
    s.curve_samples = curve_samples;
    s.require_crank = require_crank;
    s.threads = threads;
    Designs r;
    {
      py::gil_scoped_release unlocked;  // the four-bars are re-analysed on threads that call no Python
      r = SynthesiseMotion(s);
    }
    return DesignList(r);
  });
}

void BindSynthesis(py::module_& m) {
  BindClosedFormSynthesis(m);
  BindNumericalSynthesis(m);
}

}  // namespace

PYBIND11_MODULE(_koppel, m) {
  m.doc() = "koppel: planar linkages (ebene Getriebe) - the compiled part of the koppel package";
  m.attr("__version__") = Version();

  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      py::object error = py::reinterpret_borrow<py::object>(input_error.ptr())(e.what());
      py::list diagnostics;
      for (const Diagnostic& d : e.diagnostics()) {
        py::dict entry;
        entry["file"] = d.file;
        entry["line"] = d.line;
        entry["column"] = d.column;
        entry["field"] = d.path;
        entry["message"] = d.message;
        diagnostics.append(entry);
      }
      const Diagnostic first = e.diagnostics().empty() ? Diagnostic{} : e.diagnostics().front();
      error.attr("file") = first.file;
      error.attr("line") = first.line;
      error.attr("column") = first.column;
      error.attr("field") = first.path;
      error.attr("diagnostics") = diagnostics;
      PyErr_SetObject(input_error.ptr(), error.ptr());
    }
  });

  BindResults(m);
  BindModel(m);
  BindCatalog(m);
  BindSynthesis(m);
}
