// `import curvefold` (issue 30): the engine as a Python module, over the same libraries as the
// command line (pybind11). No second implementation: a design is the command line's Design with a
// live FoldSession over it (as the studio's Document), folds go through FoldSession, `check` is
// checkDesign, exports go through the same writers and OutputSet, `render` through the headless
// renderer and `replay` through the player. Errors keep the engine's one-line messages: bad input
// is ValueError, a file that cannot be read or written OSError. Long calls release the GIL.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <chrono>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/design_check.hpp"
#include "app/document.hpp"
#include "app/studio_replay.hpp"
#include "engine/fabrication/crease_pattern_pdf.hpp"
#include "engine/fabrication/cutter_svg.hpp"
#include "engine/fabrication/svg_crease_pattern.hpp"
#include "engine/geometry/creases.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/geometry/topology.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/io/design_document.hpp"
#include "engine/io/fold_format.hpp"
#include "engine/io/gltf_writer.hpp"
#include "engine/io/obj_writer.hpp"
#include "engine/io/output_set.hpp"
#include "engine/render/headless_renderer.hpp"
#include "engine/render/scene_builder.hpp"
#include "engine/simulation/bar_hinge_model.hpp"
#include "engine/simulation/design_input.hpp"
#include "engine/simulation/dynamic_solver.hpp"
#include "engine/simulation/static_solver.hpp"
#include "engine/surfaces/obj_surface.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "sim_input/recording.hpp"

namespace py = pybind11;

namespace curvefold::python {
namespace {

using session::DesignCheck;

// A point from any 3-sequence of numbers.
glm::dvec3 point3(const std::vector<double>& p, const char* what) {
  if (p.size() != 3) throw std::invalid_argument(std::string(what) + ": expected (x, y, z)");
  return {p[0], p[1], p[2]};
}

// What one fold did.
struct FoldResult {
  bool folded = false;             // false: the drop point lay within the shortest drag
  std::vector<double> grabbed;     // the surface point grabbed (x, y, z)
  std::vector<double> planePoint;  // the reflection plane
  std::vector<double> planeNormal;
  std::size_t triangles = 0;  // after the fold
  std::size_t images = 0;     // symmetric images made with it
  std::string notes;          // images skipped or overlapping, as the command says
};

// A design and the fold session over it.
class PyDesign {
 public:
  PyDesign(Design design, std::string name) : name_(std::move(name)) {
    surface_ = design.surface;
    symmetry_ = design.symmetry;
    session_ = std::make_unique<FoldSession>(initialSheet(design, name_));
    session_->applyRecords(design.folds);
    if (!symmetry_.empty()) session_->setSymmetry(parseSymmetry(symmetry_, session_->initial()));
  }

  Design design() const {
    const auto& history = session_->folds();
    return Design{surface_,
                  {history.begin(), history.begin() + std::ptrdiff_t(session_->foldCount())},
                  symmetry_};
  }
  const std::string& name() const { return name_; }
  const std::string& symmetry() const { return symmetry_; }
  FoldSession& session() { return *session_; }
  const FoldSession& session() const { return *session_; }

  // The folded sheet as it is now, shared with the arrays handed out (they stay valid after the
  // design changes: a change makes a new snapshot, one copy per change, none per array).
  std::shared_ptr<const Sheet> snapshot() const {
    if (!snapshot_ || snapshotRevision_ != session_->designRevision()) {
      snapshot_ = std::make_shared<const Sheet>(session_->fixed());
      snapshotRevision_ = session_->designRevision();
    }
    return snapshot_;
  }

  FoldResult fold(const glm::dvec3& grab, const glm::dvec3& to) {
    const std::size_t before = session_->foldCount();
    const glm::dvec3 grabbed = session_->beginDragNear(grab);
    session_->updateDrag(to);
    FoldResult result;
    result.grabbed = {grabbed.x, grabbed.y, grabbed.z};
    const ReflectionPlane plane = session_->hasPlane() ? session_->plane() : ReflectionPlane{};
    if (!session_->commit()) {
      if (!session_->refusal().empty()) throw std::invalid_argument(session_->refusal());
      result.triangles = session_->fixed().triangleCount();
      return result;
    }
    // The same check as the command line's fold.
    ValidationOptions tolerance;
    tolerance.relativeLengthTolerance =
        session::isometryTolerance(session_->initial()) / sheetSize(session_->fixed());
    try {
      validate(session_->fixed(), tolerance);
    } catch (...) {
      session_->undo();
      throw;
    }
    result.folded = true;
    result.planePoint = {plane.point.x, plane.point.y, plane.point.z};
    result.planeNormal = {plane.normal.x, plane.normal.y, plane.normal.z};
    result.triangles = session_->fixed().triangleCount();
    result.images = session_->foldCount() - before - 1;
    result.notes = imageNotes(session_->lastSkippedImages(), session_->lastOverlappingImages());
    return result;
  }

 private:
  std::string name_;
  InitialSurface surface_;
  std::string symmetry_;
  std::unique_ptr<FoldSession> session_;
  mutable std::shared_ptr<const Sheet> snapshot_;
  mutable std::uint64_t snapshotRevision_ = 0;
};

// A read-only array over `data` (rows of `columns` values of T), kept alive by `owner`.
template <typename T, typename Owner>
py::array_t<T> view(const T* data, std::size_t rows, std::size_t columns,
                    const std::shared_ptr<Owner>& owner) {
  auto* keep = new std::shared_ptr<Owner>(owner);
  py::capsule base(keep, [](void* p) { delete static_cast<std::shared_ptr<Owner>*>(p); });
  py::array_t<T> array({rows, columns}, {columns * sizeof(T), sizeof(T)}, data, base);
  py::detail::array_proxy(array.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
}

// A Design property: one of the current sheet's arrays (rows of Element, each Columns values of
// T), read-only and without a copy, kept alive by the snapshot that holds it.
template <typename T, std::size_t Columns, typename Element>
auto sheetArray(const std::vector<Element> Sheet::*rows) {
  static_assert(sizeof(Element) == Columns * sizeof(T));
  return [rows](const PyDesign& d) {
    const std::shared_ptr<const Sheet> sheet = d.snapshot();
    const std::vector<Element>& array = (*sheet).*rows;
    return view(reinterpret_cast<const T*>(array.data()), array.size(), Columns, sheet);
  };
}

py::dict surfacesInfo() {
  py::dict surfaces;
  for (const SurfaceInfo& info : surfaceCatalog()) {
    py::dict parameters;
    for (const SurfaceParameter& p : info.parameters) {
      py::dict parameter;
      parameter["default"] = p.defaultValue;
      parameter["min"] = p.min;
      parameter["max"] = p.max;
      parameter["integer"] = p.integer;
      parameter["description"] = p.description;
      parameters[py::str(p.name)] = parameter;
    }
    py::dict surface;
    surface["description"] = info.description;
    surface["parameters"] = parameters;
    surface["symmetries"] = symmetriesOf(makeSurface(info.name));
    surfaces[py::str(info.name)] = surface;
  }
  return surfaces;
}

PyDesign newDesign(const std::string& surface, const std::optional<std::string>& symmetry,
                   const py::kwargs& parameters) {
  GeneratedSurface generated{surface, {}};
  for (const auto& [key, value] : parameters)
    generated.parameters[py::cast<std::string>(key)] = py::cast<double>(value);
  makeSurface(generated.generator, generated.parameters);  // refuses bad parameters now
  Design design{generated, {}};
  if (symmetry) {
    try {
      design.symmetry = parseSymmetry(*symmetry, initialSheet(design, surface)).name();
    } catch (const InvalidSymmetry& e) {
      throw cli::UsageError("symmetry " + std::string(e.what()));
    }
  }
  return PyDesign(std::move(design), surface);
}

// An OBJ surface from a path, or from arrays through the same reader (written as OBJ text).
PyDesign designFromObj(const py::object& source,
                       const std::optional<py::array_t<double>>& triangles,
                       const std::optional<py::array_t<double>>& development) {
  if (py::isinstance<py::str>(source) || py::hasattr(source, "__fspath__")) {
    const std::string path =
        py::str(py::hasattr(source, "__fspath__") ? source.attr("__fspath__")() : source);
    return PyDesign(Design{readObjSurface(path), {}}, path);
  }
  if (!triangles) throw std::invalid_argument("from_obj: arrays need triangles=(m, 3)");
  const auto vertices =
      py::cast<py::array_t<double, py::array::c_style | py::array::forcecast>>(source);
  const auto faces =
      py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(*triangles);
  if (vertices.ndim() != 2 || vertices.shape(1) != 3)
    throw std::invalid_argument("from_obj: vertices must be an (n, 3) array");
  if (!faces || faces.ndim() != 2 || faces.shape(1) != 3)
    throw std::invalid_argument("from_obj: triangles must be an (m, 3) array");
  std::ostringstream obj;
  obj.precision(17);
  const auto v = vertices.unchecked<2>();
  for (py::ssize_t i = 0; i < v.shape(0); ++i)
    obj << "v " << v(i, 0) << ' ' << v(i, 1) << ' ' << v(i, 2) << '\n';
  if (development) {
    const auto d =
        py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(*development);
    if (!d || d.ndim() != 2 || d.shape(1) != 2 || d.shape(0) != v.shape(0))
      throw std::invalid_argument("from_obj: development must be an (n, 2) array, one per vertex");
    const auto u = d.unchecked<2>();
    for (py::ssize_t i = 0; i < u.shape(0); ++i) obj << "vt " << u(i, 0) << ' ' << u(i, 1) << '\n';
  }
  const auto f = faces.unchecked<2>();
  for (py::ssize_t i = 0; i < f.shape(0); ++i) {
    obj << 'f';
    for (int k = 0; k < 3; ++k) {
      const double index = f(i, k);
      if (!(index >= 0 && index < double(v.shape(0))) || index != std::floor(index))
        throw std::invalid_argument("from_obj: triangle " + std::to_string(i) +
                                    " names a vertex that is not there");
      const long long corner = (long long)index + 1;
      obj << ' ' << corner;
      if (development) obj << '/' << corner;
    }
    obj << '\n';
  }
  std::istringstream in(obj.str());
  return PyDesign(Design{parseObjSurface(in, "arrays"), {}}, "arrays");
}

py::dict creasesOf(const PyDesign& design) {
  const std::shared_ptr<const Sheet> sheet = design.snapshot();
  const std::vector<CreaseEdge> creases = creaseEdges(*sheet, buildEdgeTopology(*sheet));
  py::array_t<std::uint32_t> edges({py::ssize_t(creases.size()), py::ssize_t(2)});
  py::array_t<double> angles(py::ssize_t(creases.size()));
  std::vector<std::string> assignment;
  auto e = edges.mutable_unchecked<2>();
  auto a = angles.mutable_unchecked<1>();
  for (std::size_t i = 0; i < creases.size(); ++i) {
    e(i, 0) = creases[i].edge.a.value;
    e(i, 1) = creases[i].edge.b.value;
    a(i) = creases[i].foldAngle;
    assignment.push_back(creases[i].assignment == Assignment::Mountain ? "M" : "V");
  }
  py::dict result;
  result["edges"] = edges;
  result["assignment"] = assignment;
  result["angles"] = angles;
  return result;
}

// The design as a FOLD dict (json.loads of the FOLD file's text).
py::object foldDict(const PyDesign& design) {
  const std::string text = foldText(*design.snapshot());
  return py::module_::import("json").attr("loads")(text);
}

using OptionalPath = std::optional<std::filesystem::path>;

void exportDesign(const PyDesign& design, const OptionalPath& fold, const OptionalPath& svg,
                  const OptionalPath& obj, const OptionalPath& gltf, const OptionalPath& pdf,
                  const OptionalPath& cutSvg,
                  const std::optional<std::pair<double, double>>& perforate,
                  const std::string& paper, bool angles) {
  if (!fold && !svg && !obj && !gltf && !pdf && !cutSvg)
    throw std::invalid_argument("export: name at least one of fold, svg, obj, gltf, pdf, cut_svg");
  const std::optional<Paper> paperSize = parsePaper(paper);
  if (!paperSize)
    throw std::invalid_argument("export: paper must be a4, letter, a3 or fit, got '" + paper + "'");
  std::optional<Perforation> perforation;
  if (perforate) {
    if (!(perforate->first > 0.0) || !(perforate->second > 0.0) ||
        !std::isfinite(perforate->first) || !std::isfinite(perforate->second))
      throw std::invalid_argument(
          "export: perforate expects (cut, gap) in millimetres, both positive");
    perforation = Perforation{perforate->first, perforate->second};
  }
  const std::shared_ptr<const Sheet> sheet = design.snapshot();
  const Design whole = design.design();
  PdfOptions print;
  print.paper = *paperSize;
  print.angles = angles;
  print.title = design.name();
  print.facts = {"surface: " + session::surfaceName(whole) +
                     (whole.symmetry.empty() ? "" : ", " + whole.symmetry),
                 "folds: " + std::to_string(whole.folds.size())};
  py::gil_scoped_release release;
  // All named files or none, as `curvefold export` writes them.
  OutputSet outputs;
  if (fold) outputs.add(*fold, [&](const auto& at) { writeFold(*sheet, at); });
  if (svg) outputs.add(*svg, [&](const auto& at) { writeSvgCreasePattern(*sheet, at); });
  if (cutSvg)
    outputs.add(*cutSvg, [&](const auto& at) { writeCutterSvg(*sheet, at, perforation); });
  if (pdf) outputs.add(*pdf, [&](const auto& at) { writeCreasePatternPdf(*sheet, at, print); });
  if (obj) outputs.add(*obj, [&](const auto& at) { writeObj(*sheet, at); });
  if (gltf) outputs.add(*gltf, [&](const auto& at) { writeGlb(*sheet, at); });
  outputs.write();
}

// Design.simulate: the bar-and-hinge simulation (engine/simulation) of the design's flat sheet at
// a fold amount, as numpy arrays.
py::dict simulateDesign(const PyDesign& design, double percent, bool settleState,
                        std::optional<double> paperMm, std::size_t steps) {
  if (!(percent >= 0.0 && percent <= 100.0))
    throw std::invalid_argument("percent: must be from 0 to 100");
  ModelOptions options;
  if (paperMm) {
    if (!(*paperMm > 0.0 && *paperMm <= 10.0))
      throw std::invalid_argument("paper: the thickness must be above 0 and at most 10 mm");
    options.mode = SimulationMode::Paper;
    options.paper.thickness = *paperMm * 1e-3;
  }
  const std::shared_ptr<const Sheet> sheet = design.snapshot();
  BarHingeModel model;
  SimulationState state;
  StaticResult result;
  {
    py::gil_scoped_release release;
    model = buildModel(designPattern(*sheet).pattern, options);
    state = flatState(model);
    if (settleState)
      result = settle(model, percent / 100.0, state);
    else
      stepDynamic(model, percent / 100.0, state, steps);
  }
  const std::size_t n = state.positions.size(), e = model.bars.size();
  py::array_t<double> vertices({py::ssize_t(n), py::ssize_t(3)});
  auto v = vertices.mutable_unchecked<2>();
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) v(i, c) = state.positions[i][c];
  py::array_t<std::uint32_t> edges({py::ssize_t(e), py::ssize_t(2)});
  auto ed = edges.mutable_unchecked<2>();
  for (std::size_t i = 0; i < e; ++i) {
    ed(i, 0) = model.bars[i][0];
    ed(i, 1) = model.bars[i][1];
  }
  py::dict out;
  out["vertices"] = vertices;
  out["edges"] = edges;
  out["strain"] = py::array_t<double>(py::ssize_t(e), edgeStrain(model, state.positions).data());
  out["crease_angle_error"] = py::array_t<double>(
      py::ssize_t(e),
      creaseAngleError(model, state.positions, percent / 100.0, state.hingeAngles).data());
  out["converged"] = settleState ? result.converged : false;
  out["residual"] =
      settleState ? result.residual
                  : staticResidual(model, state.positions, percent / 100.0, state.hingeAngles);
  return out;
}

py::array_t<std::uint8_t> renderDesign(const PyDesign& design, std::uint32_t width,
                                       std::uint32_t height, const std::string& view,
                                       bool creasePattern) {
  const std::optional<ViewPreset> preset = parseViewPreset(view);
  if (!preset)
    throw std::invalid_argument("render: unknown view '" + view +
                                "' (known: " + std::string(kViewPresetNames) + ")");
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw std::invalid_argument("render: width and height must lie in 1 to 16384");
  const std::shared_ptr<const Sheet> sheet = design.snapshot();
  auto image = std::make_shared<RgbaImage>();
  {
    py::gil_scoped_release release;
    HeadlessOptions options;
    options.width = width;
    options.height = height;
    HeadlessRenderer renderer(options);
    *image = renderer.render(
        sceneForSheet(*sheet, *preset, float(width) / float(height), creasePattern));
  }
  auto* keep = new std::shared_ptr<RgbaImage>(image);
  py::capsule base(keep, [](void* p) { delete static_cast<std::shared_ptr<RgbaImage>*>(p); });
  return py::array_t<std::uint8_t>({py::ssize_t(height), py::ssize_t(width), py::ssize_t(4)},
                                   image->pixels.data(), base);
}

py::list foldsOf(const PyDesign& design) {
  py::list folds;
  const Design whole = design.design();
  for (const FoldRecord& fold : whole.folds) {
    py::dict item;
    item["seed"] = py::make_tuple(fold.seed.x, fold.seed.y);
    item["plane_point"] =
        py::make_tuple(fold.plane.point.x, fold.plane.point.y, fold.plane.point.z);
    item["plane_normal"] =
        py::make_tuple(fold.plane.normal.x, fold.plane.normal.y, fold.plane.normal.z);
    item["grabbed"] = py::make_tuple(fold.grabbed.x, fold.grabbed.y, fold.grabbed.z);
    item["target"] = py::make_tuple(fold.target.x, fold.target.y, fold.target.z);
    item["group"] = fold.group;
    folds.append(item);
  }
  return folds;
}

}  // namespace
}  // namespace curvefold::python

PYBIND11_MODULE(_curvefold, m) {
  using namespace curvefold;
  using namespace curvefold::python;
  m.doc() = "curvefold: curved folding by reflection (the C++ engine)";

  // The engine's one-line messages, as Python's own exceptions.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const FileError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const cli::UsageError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const DesignError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const ObjError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const InvalidSheet& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const RecordingError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const VulkanError& e) {
      PyErr_SetString(PyExc_RuntimeError, e.what());
    }
  });

  py::class_<FoldResult>(m, "FoldResult", "What one fold did.")
      .def_readonly("folded", &FoldResult::folded,
                    "False when the drop point lay within the shortest drag (nothing folded)")
      .def_readonly("grabbed", &FoldResult::grabbed, "The surface point grabbed (x, y, z)")
      .def_readonly("plane_point", &FoldResult::planePoint, "A point of the reflection plane")
      .def_readonly("plane_normal", &FoldResult::planeNormal, "The reflection plane's unit normal")
      .def_readonly("triangles", &FoldResult::triangles, "Triangles of the folded sheet")
      .def_readonly("images", &FoldResult::images, "Symmetric images made with the fold")
      .def_readonly("notes", &FoldResult::notes,
                    "Why some images were skipped or are not exactly symmetric ('' when none)")
      .def("__repr__", [](const FoldResult& r) {
        return "FoldResult(folded=" + std::string(r.folded ? "True" : "False") +
               ", triangles=" + std::to_string(r.triangles) +
               ", images=" + std::to_string(r.images) + ")";
      });

  py::class_<DesignCheck>(m, "CheckResult",
                          "The invariants `curvefold check` prints; true when all hold.")
      .def_property_readonly("passed", &DesignCheck::passed)
      .def_readonly("summary", &DesignCheck::summary, "'<name>: <surface>, N folds, ...'")
      .def_property_readonly(
          "lines",
          [](const DesignCheck& check) {
            std::vector<std::pair<bool, std::string>> lines;
            for (const session::CheckLine& line : check.lines)
              lines.emplace_back(line.ok, line.text);
            return lines;
          },
          "Every line as (ok, text), in the command's order")
      .def_property_readonly(
          "failures",
          [](const DesignCheck& check) {
            std::vector<std::string> failures;
            for (const session::CheckLine& line : check.lines)
              if (!line.ok) failures.push_back(line.text);
            return failures;
          },
          "The failing lines' texts")
      .def_readonly("self_intersections", &DesignCheck::selfIntersectingPairs,
                    "Triangle pairs that pass through each other")
      .def_readonly("contacts", &DesignCheck::contactPairs,
                    "Triangle pairs whose layers only touch (allowed)")
      .def_readonly("max_edge_length_error", &DesignCheck::maxEdgeLengthError, "Metres")
      .def_readonly("length_tolerance", &DesignCheck::lengthTolerance, "Metres")
      .def_readonly("crease_curves", &DesignCheck::creaseCurves)
      .def_readonly("mountain_edges", &DesignCheck::mountainEdges)
      .def_readonly("valley_edges", &DesignCheck::valleyEdges)
      .def("__bool__", &DesignCheck::passed)
      .def("__repr__", [](const DesignCheck& check) {
        return "<curvefold.CheckResult " + std::string(check.passed() ? "passed" : "failed: ") +
               check.firstFailure() + ">";
      });

  py::class_<PyDesign>(m, "Design", "A design: an initial surface, its folds and a symmetry.")
      .def_static("new", &newDesign, py::arg("surface"), py::kw_only(),
                  py::arg("symmetry") = py::none(),
                  "A design from a catalogue surface: Design.new('cylinder', radius=0.05, "
                  "resolution=60, symmetry='rotational:6'). Parameters as `curvefold.surfaces()` "
                  "lists them; a bad one is ValueError.")
      .def_static("from_obj", &designFromObj, py::arg("source"), py::arg("triangles") = py::none(),
                  py::arg("development") = py::none(),
                  "A design from an OBJ file (a path), or from arrays: vertices (n, 3), "
                  "triangles=(m, 3) and optionally development=(n, 2) (else it is unfolded), "
                  "read by the same OBJ reader")
      .def_static(
          "load",
          [](const std::filesystem::path& path) {
            py::gil_scoped_release release;
            return PyDesign(loadDesign(path), path.string());
          },
          py::arg("path"), "Opens a design file (*.curvefold.json)")
      .def(
          "save",
          [](const PyDesign& d, const std::filesystem::path& path) {
            const Design whole = d.design();
            py::gil_scoped_release release;
            saveDesign(whole, path);
          },
          py::arg("path"), "Writes the design file atomically (the same bytes as the command line)")
      .def("simulate", &simulateDesign, py::kw_only(), py::arg("percent") = 100.0,
           py::arg("settle") = true, py::arg("paper") = py::none(), py::arg("steps") = 2000,
           "Folds the design's flat sheet to `percent` with the bar-and-hinge simulation: to "
           "equilibrium (settle=True) or by `steps` damped dynamic steps; paper=THICKNESS_MM for "
           "paper mode. Returns a dict: vertices (n, 3), edges (e, 2), strain (e,), "
           "crease_angle_error (e,) in degrees, converged, residual")
      .def(
          "fold",
          [](PyDesign& d, const std::vector<double>& grab, const std::vector<double>& to) {
            const glm::dvec3 from = point3(grab, "grab"), drop = point3(to, "to");
            py::gil_scoped_release release;
            return d.fold(from, drop);
          },
          py::kw_only(), py::arg("grab"), py::arg("to"),
          "Grabs the surface point nearest `grab` and drops it at `to`: the part holding it is "
          "reflected through their bisector plane (with its symmetric images)")
      .def(
          "undo", [](PyDesign& d) { return d.session().undo(); },
          "Takes the last fold (and its images) back; False when there is none")
      .def(
          "redo", [](PyDesign& d) { return d.session().redo(); },
          "Makes the last undone fold again; False when there is none")
      .def_property_readonly("folds", &foldsOf,
                             "The folds, each a dict: seed, plane_point, plane_normal, grabbed, "
                             "target, group")
      .def_property_readonly("symmetry", &PyDesign::symmetry, "'' or e.g. 'rotational:6:y'")
      .def_property_readonly(
          "surface", [](const PyDesign& d) { return session::surfaceName(d.design()); },
          "The surface's name, or 'embedded mesh'")
      .def(
          "check",
          [](const PyDesign& d, bool allowSelfIntersection) {
            const std::shared_ptr<const Sheet> sheet = d.snapshot();
            const Design whole = d.design();
            DesignCheck check;
            {
              py::gil_scoped_release release;
              check = session::checkDesign(whole, d.name(), d.session().initial(), *sheet,
                                           allowSelfIntersection);
            }
            return check;
          },
          py::arg("allow_self_intersection") = false,
          "The invariants `curvefold check` prints, as a CheckResult (true when all hold; "
          "self-intersections and contacts included)")
      .def_property_readonly("vertices", sheetArray<double, 3>(&Sheet::positions),
                             "Folded positions, (n, 3) float64, read-only (no copy)")
      .def_property_readonly("development", sheetArray<double, 2>(&Sheet::development),
                             "The flat paper, (n, 2) float64, read-only (no copy)")
      .def_property_readonly("triangles", sheetArray<std::uint32_t, 3>(&Sheet::triangles),
                             "Triangles, (m, 3) uint32 vertex indices, counter-clockwise in the "
                             "development, read-only (no copy)")
      .def("creases", &creasesOf,
           "Crease edges: edges (k, 2) uint32, assignment ['M' or 'V'], angles (k,) degrees "
           "(FOLD's convention)")
      .def("to_fold", &foldDict, "The design as a FOLD dict (the FOLD file's content)")
      .def("export", &exportDesign, py::kw_only(), py::arg("fold") = py::none(),
           py::arg("svg") = py::none(), py::arg("obj") = py::none(), py::arg("gltf") = py::none(),
           py::arg("pdf") = py::none(), py::arg("cut_svg") = py::none(),
           py::arg("perforate") = py::none(), py::arg("paper") = "a4", py::arg("angles") = false,
           "Writes the named files, all or none (as `curvefold export`)")
      .def("render", &renderDesign, py::arg("width") = 800, py::arg("height") = 600, py::kw_only(),
           py::arg("view") = "iso", py::arg("crease_pattern") = false,
           "The folded form as an (height, width, 4) uint8 RGBA image (headless Vulkan)")
      .def("__repr__", [](const PyDesign& d) {
        return "<curvefold.Design " + session::surfaceName(d.design()) + ", " +
               std::to_string(d.session().foldCount()) + " folds" +
               (d.symmetry().empty() ? "" : ", " + d.symmetry()) + ">";
      });

  // For the overhead benchmark (python/bench/fold_overhead.py): the same fold as Design.fold,
  // timed in C++ without the binding, each taken back; seconds per fold.
  m.def(
      "_time_folds_in_cpp",
      [](PyDesign& d, const std::vector<double>& grab, const std::vector<double>& to,
         std::size_t repeats) {
        const glm::dvec3 from = point3(grab, "grab"), drop = point3(to, "to");
        std::vector<double> seconds;
        py::gil_scoped_release release;
        for (std::size_t i = 0; i < repeats; ++i) {
          const auto start = std::chrono::steady_clock::now();
          const FoldResult result = d.fold(from, drop);
          seconds.push_back(
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
          if (result.folded) d.session().undo();
        }
        return seconds;
      },
      py::arg("design"), py::arg("grab"), py::arg("to"), py::arg("repeats"));
  m.def("surfaces", &surfacesInfo,
        "The catalogue: {name: {description, parameters: {name: {default, min, max, integer, "
        "description}}, symmetries}}");
  m.def(
      "replay",
      [](const std::filesystem::path& recording) {
        py::gil_scoped_release release;
        const ReplayResult result = studio::replayAnyRecording(readRecording(recording));
        return PyDesign(result.design, recording.string());
      },
      py::arg("recording"), "The design a recording (*.jsonl) makes, replayed headless");
}
