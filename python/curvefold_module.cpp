// `import curvefold` (issue 30): the engine as a Python module, over the same libraries as the
// command line (pybind11). No second implementation: a design is the command line's Design with a
// live FoldSession over it (as the studio's Document), folds go through FoldSession, `check` is
// checkDesign, exports go through the same writers and OutputSet, `render` through the headless
// renderer and `replay` through the player. Errors keep the engine's one-line messages: bad input
// is ValueError, a file that cannot be read or written OSError; arguments are converted here by
// name, so a bad one names its parameter. Long calls release the GIL; a Design may be used from
// several threads (DesignGuard, below).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "app/session/design_check.hpp"
#include "app/session/document.hpp"
#include "app/session/guarded_design.hpp"
#include "app/session/printed_cover.hpp"
#include "app/studio/studio_replay.hpp"
#include "engine/fabrication/crease_pattern_pdf.hpp"
#include "engine/fabrication/cutter_svg.hpp"
#include "engine/fabrication/svg_crease_pattern.hpp"
#include "engine/fit/fit_start.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/fit/runner_up_fits.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/geometry/creases.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/geometry/topology.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/io/crease_pattern_graph.hpp"
#include "engine/io/crease_pattern_reader.hpp"
#include "engine/io/design_document.hpp"
#include "engine/io/fold_crease_pattern.hpp"
#include "engine/io/fold_format.hpp"
#include "engine/io/gltf_writer.hpp"
#include "engine/io/input_limits.hpp"
#include "engine/io/obj_writer.hpp"
#include "engine/io/output_set.hpp"
#include "engine/render/field_picture.hpp"
#include "engine/render/headless_renderer.hpp"
#include "engine/render/scene_builder.hpp"
#include "engine/simulation/bar_hinge_model.hpp"
#include "engine/simulation/design_input.hpp"
#include "engine/simulation/dynamic_solver.hpp"
#include "engine/simulation/simulate_options.hpp"
#include "engine/simulation/state_report.hpp"
#include "engine/simulation/static_solver.hpp"
#include "engine/surfaces/obj_surface.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "sim_input/recording.hpp"

namespace py = pybind11;

namespace curvefold::python {
namespace {

using session::DesignCheck;

// Arguments (issue 40, 3): each converted here, by name, so a bad one is one line naming its
// parameter: a value of the wrong type is ArgumentTypeError (curvefold.ArgumentError, both a
// ValueError and a TypeError), a bad value of the right type std::invalid_argument (ValueError).
// A file that cannot be read or written is FileError (OSError) naming the path.
class ArgumentTypeError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// "str '0.2'", "NoneType None": what was given, shortened.
std::string given(const py::handle& value) {
  if (py::isinstance<py::array>(value)) {
    std::string shape;
    for (const py::handle& n : value.attr("shape"))
      shape += (shape.empty() ? "" : ", ") + std::string(py::str(n));
    return "an array of shape (" + shape + (value.attr("ndim").cast<int>() == 1 ? ",)" : ")");
  }
  std::string shown = py::str(py::repr(value));
  std::replace(shown.begin(), shown.end(), '\n', ' ');
  if (shown.size() > 40) shown = shown.substr(0, 37) + "...";
  return std::string(Py_TYPE(value.ptr())->tp_name) + " " + shown;
}

double number(const py::handle& value, const std::string& name) {
  const bool isNumber = PyFloat_Check(value.ptr()) || PyIndex_Check(value.ptr()) ||
                        (py::hasattr(value, "__float__") && !py::isinstance<py::array>(value) &&
                         !py::isinstance<py::str>(value));
  if (!isNumber) throw ArgumentTypeError(name + ": expected a number, got " + given(value));
  const double x = PyFloat_AsDouble(value.ptr());
  if (x == -1.0 && PyErr_Occurred()) {
    PyErr_Clear();
    throw std::invalid_argument(name + ": " + given(value) + " is out of range");
  }
  return x;
}

std::int64_t integer(const py::handle& value, const std::string& name) {
  if (!PyIndex_Check(value.ptr()) || PyBool_Check(value.ptr()))
    throw ArgumentTypeError(name + ": expected an integer, got " + given(value));
  const Py_ssize_t n = PyNumber_AsSsize_t(value.ptr(), nullptr);
  if (n == -1 && PyErr_Occurred()) {
    PyErr_Clear();
    throw std::invalid_argument(name + ": " + given(value) + " is out of range");
  }
  return n;
}

bool flag(const py::handle& value, const std::string& name) {
  if (!PyBool_Check(value.ptr()) && std::string(Py_TYPE(value.ptr())->tp_name) != "numpy.bool_")
    throw ArgumentTypeError(name + ": expected True or False, got " + given(value));
  return value.cast<bool>();
}

std::string text(const py::handle& value, const std::string& name) {
  if (!py::isinstance<py::str>(value))
    throw ArgumentTypeError(name + ": expected a str, got " + given(value));
  return value.cast<std::string>();
}

std::filesystem::path filePath(const py::handle& value, const std::string& name) {
  const bool pathLike = py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value) ||
                        py::hasattr(value, "__fspath__");
  if (!pathLike)
    throw ArgumentTypeError(name + ": expected a path (str or os.PathLike), got " + given(value));
  const std::filesystem::path path = value.cast<std::filesystem::path>();
  if (path.empty()) throw std::invalid_argument(name + ": the path is empty");
  return path;
}

std::optional<std::filesystem::path> optionalPath(const py::handle& value,
                                                  const std::string& name) {
  if (value.is_none()) return std::nullopt;
  return filePath(value, name);
}

// A point: any three numbers, (3,) or a 3-sequence; not (3, 1), not NaN.
glm::dvec3 point3(const py::handle& value, const std::string& name) {
  const auto a = py::array_t<double, py::array::forcecast>::ensure(value);
  if (!a || py::isinstance<py::str>(value))
    throw ArgumentTypeError(name + ": expected (x, y, z), got " + given(value));
  if (a.ndim() != 1 || a.shape(0) != 3)
    throw std::invalid_argument(name + ": expected (x, y, z), three numbers, got " + given(value));
  const glm::dvec3 p{a.at(0), a.at(1), a.at(2)};
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    throw std::invalid_argument(name + ": expected finite coordinates, got " + given(value));
  return p;
}

// An input file, checked before it is opened: a path that names no regular file (missing, a
// folder, a FIFO that would block, a device) is FileError naming it; one over `maxBytes` is the
// reader's own limit message, as ValueError (a limit is about the input's value, not the disk).
void checkInputFile(const std::filesystem::path& path, std::uint64_t maxBytes = 0,
                    std::string_view kind = {}) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status))
    throw FileError("cannot read " + path.string() + ": " + std::strerror(ENOENT));
  if (std::filesystem::is_directory(status))
    throw FileError("cannot read " + path.string() + ": " + std::strerror(EISDIR));
  if (!std::filesystem::is_regular_file(status))
    throw FileError("cannot read " + path.string() +
                    ": not a regular file (a FIFO, socket or device)");
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (maxBytes > 0 && !error && size > maxBytes)
    throw std::invalid_argument(tooLarge(path.string(), size, maxBytes, kind));
}

using session::FoldResult;
// The module's Design: safe to call from several Python threads at once (issue 40, 2), and the
// file it was read from, which its outputs must not overwrite (set before the design is shared).
class PyDesign : public session::GuardedDesign {
 public:
  PyDesign(Design design, std::string name, std::filesystem::path source = {},
           bool sourceIsDesign = false)
      : GuardedDesign(std::move(design), std::move(name)),
        source_(std::move(source)),
        sourceIsDesign_(sourceIsDesign) {}

  // Refuses an output that names the file the design came from (save may write a design file
  // again, as `curvefold fold D -o D` does; nothing writes over an OBJ or a recording).
  void checkOutput(const std::filesystem::path& output, const std::string& parameter,
                   bool designFile = false) const {
    if (source_.empty() || (designFile && sourceIsDesign_)) return;
    if (sameFile(output, source_))
      throw std::invalid_argument(parameter + ": " + output.string() +
                                  " is the file this design was read from; write to another file");
  }

 private:
  std::filesystem::path source_;
  bool sourceIsDesign_ = false;
};

// Every Design method that reads or writes the design holds one of these while it does: the GIL
// is released first, then the design's lock is taken (released, then the GIL taken back, at the
// end of its scope). So a thread waiting for a design lets Python run and never holds the GIL
// while it waits; Python objects are made after the guard's scope. Construct it with the GIL held.
class DesignGuard {
 public:
  explicit DesignGuard(const PyDesign& design) : lock(design) {}

 private:
  py::gil_scoped_release gil_;  // first: released before waiting for the lock

 public:
  const PyDesign::Lock lock;
};

// The sheet as it is now (immutable: read it with the GIL held or not, no guard needed).
std::shared_ptr<const Sheet> snapshotOf(const PyDesign& design) {
  DesignGuard guard(design);
  return design.snapshot(guard.lock);
}

Design designOf(const PyDesign& design) {
  DesignGuard guard(design);
  return design.design(guard.lock);
}

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

// One of a sheet's arrays (rows of Element, each Columns values of T), read-only and without a
// copy, kept alive by the snapshot that holds it.
template <typename T, std::size_t Columns, typename Element>
py::array_t<T> sheetView(const std::shared_ptr<const Sheet>& sheet,
                         const std::vector<Element> Sheet::*rows) {
  static_assert(sizeof(Element) == Columns * sizeof(T));
  const std::vector<Element>& array = (*sheet).*rows;
  return view(reinterpret_cast<const T*>(array.data()), array.size(), Columns, sheet);
}

// A Design property: one of the current sheet's arrays.
template <typename T, std::size_t Columns, typename Element>
auto sheetArray(const std::vector<Element> Sheet::*rows) {
  return [rows](const PyDesign& d) { return sheetView<T, Columns>(snapshotOf(d), rows); };
}

// (vertices, triangles, development) of one state of the design: separate property reads may
// see a fold another thread made between them.
py::tuple meshArrays(const PyDesign& design) {
  const std::shared_ptr<const Sheet> sheet = snapshotOf(design);
  return py::make_tuple(sheetView<double, 3>(sheet, &Sheet::positions),
                        sheetView<std::uint32_t, 3>(sheet, &Sheet::triangles),
                        sheetView<double, 2>(sheet, &Sheet::development));
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

PyDesign newDesign(const py::object& surfaceName, const py::object& symmetryName,
                   const py::kwargs& parameters) {
  const std::string surface = text(surfaceName, "surface");
  const std::optional<std::string> symmetry =
      symmetryName.is_none() ? std::nullopt : std::optional(text(symmetryName, "symmetry"));
  GeneratedSurface generated{surface, {}};
  for (const auto& [key, value] : parameters) {
    const std::string name = py::cast<std::string>(key);
    generated.parameters[name] = number(value, name);
  }
  makeSurface(generated.generator, generated.parameters);  // refuses bad parameters now
  Design design{generated, {}};
  if (symmetry) {
    try {
      design.symmetry = parseSymmetry(*symmetry, initialSheet(design, surface)).name();
    } catch (const InvalidSymmetry& e) {
      throw std::invalid_argument("symmetry " + session::symmetryProblem(e));
    }
  }
  return PyDesign(std::move(design), surface);
}

// An OBJ surface from a path, or from arrays through the same reader (written as OBJ text).
PyDesign designFromObj(const py::object& source, const py::object& triangles,
                       const py::object& development) {
  if (py::isinstance<py::str>(source) || py::isinstance<py::bytes>(source) ||
      py::hasattr(source, "__fspath__")) {
    const std::filesystem::path path = filePath(source, "source");
    py::gil_scoped_release release;  // a long read; nothing here blocks: regular files only
    checkInputFile(path);
    return PyDesign(Design{readObjSurface(path.string()), {}}, path.string(), path);
  }
  if (triangles.is_none()) throw std::invalid_argument("from_obj: arrays need triangles=(m, 3)");
  const auto vertices =
      py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(source);
  const auto faces =
      py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(triangles);
  if (!vertices || vertices.ndim() != 2 || vertices.shape(1) != 3)
    throw std::invalid_argument("from_obj: vertices must be an (n, 3) array");
  if (!faces || faces.ndim() != 2 || faces.shape(1) != 3)
    throw std::invalid_argument("from_obj: triangles must be an (m, 3) array");
  std::ostringstream obj;
  obj.precision(17);
  const auto v = vertices.unchecked<2>();
  for (py::ssize_t i = 0; i < v.shape(0); ++i)
    obj << "v " << v(i, 0) << ' ' << v(i, 1) << ' ' << v(i, 2) << '\n';
  if (!development.is_none()) {
    const auto d =
        py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(development);
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
      if (!development.is_none()) obj << '/' << corner;
    }
    obj << '\n';
  }
  std::istringstream in(obj.str());
  return PyDesign(Design{parseObjSurface(in, "arrays"), {}}, "arrays");
}

py::dict creasesOf(const PyDesign& design) {
  const std::shared_ptr<const Sheet> sheet = snapshotOf(design);
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
  const std::string text = foldText(*snapshotOf(design));
  return py::module_::import("json").attr("loads")(text);
}

using OptionalPath = std::optional<std::filesystem::path>;

void exportDesign(const PyDesign& design, const py::object& foldArg, const py::object& svgArg,
                  const py::object& objArg, const py::object& gltfArg, const py::object& pdfArg,
                  const py::object& cutSvgArg, const py::object& perforateArg,
                  const py::object& paperArg, const py::object& anglesArg) {
  const OptionalPath fold = optionalPath(foldArg, "fold"), svg = optionalPath(svgArg, "svg"),
                     obj = optionalPath(objArg, "obj"), gltf = optionalPath(gltfArg, "gltf"),
                     pdf = optionalPath(pdfArg, "pdf"), cutSvg = optionalPath(cutSvgArg, "cut_svg");
  const std::string paper = text(paperArg, "paper");
  const bool angles = flag(anglesArg, "angles");
  std::optional<std::pair<double, double>> perforate;
  if (!perforateArg.is_none()) {
    if (!py::isinstance<py::sequence>(perforateArg) || py::isinstance<py::str>(perforateArg) ||
        py::len(perforateArg) != 2)
      throw ArgumentTypeError("perforate: expected (cut, gap) in millimetres, got " +
                              given(perforateArg));
    perforate = {number(perforateArg[py::int_(0)], "perforate"),
                 number(perforateArg[py::int_(1)], "perforate")};
  }
  if (!fold && !svg && !obj && !gltf && !pdf && !cutSvg)
    throw std::invalid_argument("export: name at least one of fold, svg, obj, gltf, pdf, cut_svg");
  for (const auto& [path, parameter] : {std::pair{&fold, "fold"},
                                        {&svg, "svg"},
                                        {&obj, "obj"},
                                        {&gltf, "gltf"},
                                        {&pdf, "pdf"},
                                        {&cutSvg, "cut_svg"}})
    if (*path) design.checkOutput(**path, parameter);
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
  std::shared_ptr<const Sheet> sheet;
  Design whole;
  {
    DesignGuard guard(design);
    sheet = design.snapshot(guard.lock);
    whole = design.design(guard.lock);
  }
  // The cover `curvefold export --pdf` prints: the facts with the date, the folded form.
  PdfOptions print;
  print.paper = *paperSize;
  print.angles = angles;
  print.title = session::designName(design.name());  // "vase", not "vase.curvefold.json"
  print.facts = session::coverFacts(whole);
  std::string noPicture;
  {
    py::gil_scoped_release release;
    if (pdf) print.picture = session::renderFoldedForm(*sheet, noPicture);
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
  // Written all the same, as the command line writes it (which says so on standard error).
  if (!noPicture.empty() &&
      PyErr_WarnEx(PyExc_RuntimeWarning,
                   ("the PDF goes without the picture of the folded form: " + noPicture).c_str(),
                   1) < 0)
    throw py::error_already_set();  // warnings made errors (python -W error)
}

// What a simulation is asked for (Design.simulate and curvefold.simulate), checked by name. Pins
// and glue name points of the flat sheet, taken to vertices once the pattern is read: each a
// point or the command line's text for it ("X,Y"; "X1,Y1:X2,Y2" or "slits").
struct SimulateArguments {
  double percent = 100.0;
  bool settle = true;
  std::size_t steps = 2000;
  bool motion = false;
  double sizeMetres = 0.0;  // curvefold.simulate's size=, 0: as the pattern states
  ModelOptions model;
  std::vector<std::variant<std::string, glm::dvec2>> pins;
  std::vector<std::variant<std::string, std::array<glm::dvec2, 2>>> glue;
};

// The keywords of Design.simulate and curvefold.simulate as given (size: the latter's only).
struct SimulateKeywords {
  py::object percent, settle, paper, modulus, contact, steps, stiffness, motion, pin, glue;
  py::object size = py::none();
};

// Two numbers, (2,) or a 2-sequence; finiteness is the engine's to check (sheetVertexNear).
std::optional<glm::dvec2> point2(const py::handle& value) {
  if (py::isinstance<py::str>(value)) return std::nullopt;
  const auto a = py::array_t<double, py::array::forcecast>::ensure(value);
  if (!a || a.ndim() != 1 || a.shape(0) != 2) return std::nullopt;
  return glm::dvec2{a.at(0), a.at(1)};
}

// The items of a list, tuple or array (not a str, which is one item where `single` says so).
std::vector<py::object> items(const py::handle& value, const std::string& name,
                              const std::string& expected, bool single) {
  if (single && py::isinstance<py::str>(value)) return {py::reinterpret_borrow<py::object>(value)};
  if (py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value) ||
      !(py::isinstance<py::sequence>(value) || py::isinstance<py::array>(value)))
    throw ArgumentTypeError(name + ": expected " + expected + ", got " + given(value));
  std::vector<py::object> out;
  for (const py::handle& item : value) out.push_back(py::reinterpret_borrow<py::object>(item));
  return out;
}

// pin=[(x, y) or "X,Y", ...] (--pin, repeated).
std::vector<std::variant<std::string, glm::dvec2>> pinArguments(const py::handle& value) {
  const std::string expected = "a list of points (x, y) on the flat sheet in metres";
  std::vector<std::variant<std::string, glm::dvec2>> pins;
  if (value.is_none()) return pins;
  for (const py::object& item : items(value, "pin", expected, false)) {
    if (py::isinstance<py::str>(item)) {
      pins.emplace_back(item.cast<std::string>());
    } else if (const std::optional<glm::dvec2> p = point2(item)) {
      pins.emplace_back(*p);
    } else {
      throw ArgumentTypeError("pin: expected " + expected + ", got an item " + given(item));
    }
  }
  return pins;
}

// glue="slits", or [((x1, y1), (x2, y2)) or "X1,Y1:X2,Y2" or "slits", ...] (--glue, repeated).
std::vector<std::variant<std::string, std::array<glm::dvec2, 2>>> glueArguments(
    const py::handle& value) {
  const std::string expected =
      "\"slits\" or a list of point pairs ((x1, y1), (x2, y2)) on the flat sheet in metres";
  std::vector<std::variant<std::string, std::array<glm::dvec2, 2>>> glue;
  if (value.is_none()) return glue;
  for (const py::object& item : items(value, "glue", expected, true)) {
    if (py::isinstance<py::str>(item)) {
      glue.emplace_back(item.cast<std::string>());
      continue;
    }
    std::optional<glm::dvec2> a, b;
    if (!py::isinstance<py::str>(item) &&
        (py::isinstance<py::sequence>(item) || py::isinstance<py::array>(item)) &&
        py::len(item) == 2) {
      a = point2(item[py::int_(0)]);
      b = point2(item[py::int_(1)]);
    }
    if (!a || !b)
      throw ArgumentTypeError("glue: expected " + expected + ", got an item " + given(item));
    glue.push_back(std::array<glm::dvec2, 2>{*a, *b});
  }
  return glue;
}

// Everything but pins and glue is checked before the pattern is read, in the command line's order
// and by its functions: stiffness (setStiffnessPreset), paper mode (setPaperMode, the same modulus
// default and self-contact), size (sheetSizeMetres); so `curvefold simulate INPUT --paper T` and
// simulate(paper=T) give the same state bit for bit.
SimulateArguments simulateArguments(const SimulateKeywords& keywords) {
  SimulateArguments arguments;
  arguments.percent = number(keywords.percent, "percent");
  arguments.settle = flag(keywords.settle, "settle");
  std::optional<double> paperMm, modulusGpa;
  if (!keywords.paper.is_none()) paperMm = number(keywords.paper, "paper");
  if (!keywords.modulus.is_none()) modulusGpa = number(keywords.modulus, "modulus");
  const bool contact = flag(keywords.contact, "contact");
  const std::int64_t steps = integer(keywords.steps, "steps");
  arguments.motion = flag(keywords.motion, "motion");
  std::optional<std::string> stiffness;
  if (!keywords.stiffness.is_none()) stiffness = text(keywords.stiffness, "stiffness");
  std::optional<double> sizeMm;
  if (!keywords.size.is_none()) sizeMm = number(keywords.size, "size");
  arguments.pins = pinArguments(keywords.pin);
  arguments.glue = glueArguments(keywords.glue);
  if (!(arguments.percent >= 0.0 && arguments.percent <= 100.0))
    throw std::invalid_argument("percent: must be from 0 to 100");
  if (steps < 0 || steps > 10'000'000)
    throw std::invalid_argument("steps: must lie in 0 to 10000000");
  arguments.steps = static_cast<std::size_t>(steps);
  if (stiffness) setStiffnessPreset(arguments.model, *stiffness, paperMm.has_value());
  if (paperMm) {
    // "paper: ..." or "modulus: ..." for a value out of range (ValueError).
    setPaperMode(arguments.model, *paperMm, modulusGpa.value_or(kDefaultPaperModulusGpa), contact);
  } else if (modulusGpa) {
    throw std::invalid_argument("modulus: only paper mode (paper=THICKNESS_MM) has a modulus");
  } else if (!contact) {
    throw std::invalid_argument("contact: only paper mode (paper=THICKNESS_MM) has self-contact");
  }
  if (sizeMm) arguments.sizeMetres = sheetSizeMetres(*sizeMm);
  return arguments;
}

// The pins and glue on the pattern read, in the command line's order (every pin, then the glue).
void placePinsAndGlue(SimulateArguments& arguments, const CreasePattern& pattern,
                      const std::vector<std::pair<std::uint32_t, std::uint32_t>>& seams) {
  for (const auto& pin : arguments.pins) {
    if (const auto* text = std::get_if<std::string>(&pin))
      addPin(arguments.model, pattern, parseSheetPoint(*text, "pin"));
    else
      addPin(arguments.model, pattern, std::get<glm::dvec2>(pin));
  }
  for (const auto& glue : arguments.glue) {
    if (const auto* text = std::get_if<std::string>(&glue))
      addGlueText(arguments.model, pattern, seams, *text);
    else
      addGlue(arguments.model, pattern, std::get<1>(glue)[0], std::get<1>(glue)[1]);
  }
}

// The bar-and-hinge simulation (engine/simulation) of a crease pattern from flat to the fold
// amount, as numpy arrays: vertices (n, 3), development (n, 2), triangles (m, 3), edges (e, 2)
// with their assignment letters, strain and crease angle error per edge, and what `curvefold
// simulate` prints of the state (reportState: largest strain, crease angle errors, creases on the
// wrong side, crossing triangle pairs; converged, iterations, residual, energy), and with motion
// the folding motion's line. Call with the GIL held; it is released while the model is built and
// solved.
py::dict simulatePattern(const CreasePattern& pattern, SimulateArguments arguments,
                         const std::vector<std::pair<std::uint32_t, std::uint32_t>>& seams = {}) {
  placePinsAndGlue(arguments, pattern, seams);
  BarHingeModel model;
  SimulationState state;
  StaticResult result;
  FoldingMotion motion;
  StateReport report;
  const double amount = arguments.percent / 100.0;
  double residual = 0.0;
  {
    py::gil_scoped_release release;
    model = buildModel(pattern, arguments.model);
    if (arguments.motion) motion = followFoldingMotion(model);
    state = flatState(model);
    if (arguments.settle)
      result = settle(model, amount, state);
    else
      stepDynamic(model, amount, state, arguments.steps);
    report = reportState(model, state, amount);
    residual = arguments.settle ? result.residual
                                : staticResidual(model, state.positions, amount, state.hingeAngles);
  }
  const std::size_t n = state.positions.size(), e = model.bars.size(), m = pattern.triangles.size();
  py::array_t<double> vertices({py::ssize_t(n), py::ssize_t(3)});
  py::array_t<double> development({py::ssize_t(n), py::ssize_t(2)});
  auto v = vertices.mutable_unchecked<2>();
  auto d = development.mutable_unchecked<2>();
  for (std::size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) v(i, c) = state.positions[i][c];
    d(i, 0) = pattern.vertices[i].x;
    d(i, 1) = pattern.vertices[i].y;
  }
  py::array_t<std::uint32_t> triangles({py::ssize_t(m), py::ssize_t(3)});
  auto t = triangles.mutable_unchecked<2>();
  for (std::size_t i = 0; i < m; ++i)
    for (int c = 0; c < 3; ++c) t(i, c) = pattern.triangles[i][c];
  py::array_t<std::uint32_t> edges({py::ssize_t(e), py::ssize_t(2)});
  auto ed = edges.mutable_unchecked<2>();
  std::string assignment;
  for (std::size_t i = 0; i < e; ++i) {
    ed(i, 0) = model.bars[i][0];
    ed(i, 1) = model.bars[i][1];
    assignment += foldLetter(pattern.edges[i].assignment);
  }
  py::dict out;
  out["vertices"] = vertices;
  out["development"] = development;
  out["triangles"] = triangles;
  out["edges"] = edges;
  out["assignment"] = assignment;
  out["strain"] = py::array_t<double>(py::ssize_t(e), report.strain.data());
  out["crease_angle_error"] = py::array_t<double>(py::ssize_t(e), report.angleError.data());
  out["largest_strain"] = report.largestStrain;
  out["largest_crease_angle_error"] = report.largestAngleError;
  out["mean_crease_angle_error"] = report.meanAngleError;
  out["wrong_side_creases"] = report.wrongSideCreases;
  out["past_flat_creases"] = report.pastFlatCreases;
  out["crossing_pairs"] = report.crossingPairs;
  out["converged"] = arguments.settle ? result.converged : false;
  out["iterations"] = arguments.settle ? result.iterations : std::size_t(0);
  out["energy_rises"] = arguments.settle ? energyRises(result.history) : std::size_t(0);
  out["residual"] = residual;
  // Settled at the rounding floor (static_solver.hpp): converged with a residual above the
  // tolerance that no representable move can lower, and that floor.
  out["at_rounding_floor"] = arguments.settle && result.atRoundingFloor;
  out["rounding_floor"] = arguments.settle ? result.roundingFloor : 0.0;
  if (arguments.settle) out["energy"] = result.energy;
  if (arguments.motion) {
    py::dict line;
    line["states"] = motion.amounts.size();
    line["followed_to"] = 100.0 * motion.amounts[motion.amounts.size() - 2];
    line["reached_full"] = motion.reachedFull;
    out["motion"] = line;
  }
  out["notes"] = pattern.notes;
  return out;
}

// Design.simulate: the design's flat sheet folded toward the design.
// glue="slits" glues its slits (designPattern's seams), as `--glue slits`.
py::dict simulateDesign(const PyDesign& design, const SimulateKeywords& keywords) {
  const SimulateArguments arguments = simulateArguments(keywords);
  const std::shared_ptr<const Sheet> sheet = snapshotOf(design);
  DesignPattern pattern;
  {
    py::gil_scoped_release release;
    pattern = designPattern(*sheet);
  }
  return simulatePattern(pattern.pattern, arguments, pattern.seams);
}

// curvefold.simulate: a crease pattern from another tool, as a FOLD dict (what json.load gives;
// numpy arrays in it are taken as lists) or a path to a FOLD or SVG file, read as `curvefold
// simulate` reads it. Messages about a dict start "pattern: ".
// size=MM scales it as --size does (after its frame_unit or the SVG's size).
py::dict simulateCreasePattern(const py::object& source, const SimulateKeywords& keywords) {
  const SimulateArguments arguments = simulateArguments(keywords);
  CreasePattern pattern;
  if (py::isinstance<py::dict>(source)) {
    const py::cpp_function asList([](const py::object& value) -> py::object {
      if (py::hasattr(value, "tolist")) return value.attr("tolist")();
      throw py::type_error(std::string(Py_TYPE(value.ptr())->tp_name) + " is not a JSON value");
    });
    std::string text;
    try {
      text = py::module_::import("json")
                 .attr("dumps")(source, py::arg("allow_nan") = false, py::arg("default") = asList)
                 .cast<std::string>();
    } catch (const py::error_already_set& e) {
      if (e.matches(PyExc_ValueError))  // allow_nan=False
        throw std::invalid_argument("pattern: holds a NaN or infinite number");
      std::string why = py::str(e.value());
      why = why.substr(0, why.find('\n'));
      throw std::invalid_argument("pattern: not a FOLD dict (" + why + ")");
    }
    py::gil_scoped_release release;
    pattern = readFoldCreasePatternText(text, "pattern");
    scaleToMetres(pattern);  // its frame_unit, as a file's
  } else if (py::isinstance<py::str>(source) || py::isinstance<py::bytes>(source) ||
             py::hasattr(source, "__fspath__")) {
    const std::filesystem::path path = filePath(source, "pattern");
    py::gil_scoped_release release;
    checkInputFile(path, kMaxCreasePatternBytes, "crease pattern");
    pattern = readCreasePattern(path);
  } else {
    throw ArgumentTypeError(
        "pattern: expected a FOLD dict or the path of a .fold or .svg file, got " + given(source));
  }
  if (arguments.sizeMetres > 0.0) scaleToSize(pattern, arguments.sizeMetres);
  return simulatePattern(pattern, arguments);
}

py::array_t<std::uint8_t> renderDesign(const PyDesign& design, const py::object& widthArg,
                                       const py::object& heightArg, const py::object& viewArg,
                                       const py::object& creasePatternArg) {
  const std::int64_t width = integer(widthArg, "width"), height = integer(heightArg, "height");
  const std::string view = text(viewArg, "view");
  const bool creasePattern = flag(creasePatternArg, "crease_pattern");
  const std::optional<ViewPreset> preset = parseViewPreset(view);
  if (!preset)
    throw std::invalid_argument("render: unknown view '" + view +
                                "' (known: " + std::string(kViewPresetNames) + ")");
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw std::invalid_argument("render: width and height must lie in 1 to 16384");
  const std::shared_ptr<const Sheet> sheet = snapshotOf(design);
  auto image = std::make_shared<RgbaImage>();
  {
    py::gil_scoped_release release;
    HeadlessOptions options;
    options.width = std::uint32_t(width);
    options.height = std::uint32_t(height);
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
  const Design whole = designOf(design);
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

// A shape to fit or measure: a Design (its folded form), an OBJ file, or a design file (its
// folded form), as `curvefold fit` and `curvefold distance` read them.
TriangleMesh shapeOf(const py::object& shape, const char* what) {
  if (py::isinstance<PyDesign>(shape)) return meshOf(*snapshotOf(py::cast<const PyDesign&>(shape)));
  if (!py::isinstance<py::str>(shape) && !py::hasattr(shape, "__fspath__"))
    throw std::invalid_argument(std::string(what) + ": expected a Design or a path");
  const std::string path =
      py::str(py::hasattr(shape, "__fspath__") ? shape.attr("__fspath__")() : shape);
  py::gil_scoped_release release;
  if (std::filesystem::path(path).extension() == ".obj") return readObjMesh(path);
  const session::GuardedDesign design(loadDesign(path), path);
  return meshOf(*design.snapshot(session::GuardedDesign::Lock(design)));
}

std::string shapeName(const py::object& shape) {
  if (py::isinstance<PyDesign>(shape)) return py::cast<const PyDesign&>(shape).name();
  return py::str(py::hasattr(shape, "__fspath__") ? shape.attr("__fspath__")() : shape);
}

py::dict distanceDict(const SurfaceDistance& d) {
  py::dict result;
  result["hausdorff"] = d.hausdorff;
  result["chamfer"] = d.chamfer;
  result["diagonal"] = d.diagonal;
  result["hausdorff_relative"] = d.relativeHausdorff();
  result["chamfer_relative"] = d.relativeChamfer();
  result["a_to_b_max"] = d.fromAMax;
  result["a_to_b_mean"] = d.fromAMean;
  result["b_to_a_max"] = d.fromBMax;
  result["b_to_a_mean"] = d.fromBMean;
  return result;
}

// `curvefold distance A B [--png P]`: the same samples, the same numbers, the same picture (A
// coloured by its distance to B; a Design is drawn with its creases, a file's shape without).
py::dict distanceOf(const py::object& a, const py::object& b, std::size_t samples,
                    std::uint64_t seed, const py::object& pngArg) {
  if (samples < 100 || samples > 10'000'000)
    throw std::invalid_argument("distance: samples must lie in 100 to 10000000");
  const std::optional<std::filesystem::path> png = optionalPath(pngArg, "distance: png");
  if (png) {
    std::vector<NamedInput> inputs;
    if (!py::isinstance<PyDesign>(a)) inputs.push_back({shapeName(a), "a"});
    if (!py::isinstance<PyDesign>(b)) inputs.push_back({shapeName(b), "b"});
    refuseOutputsOverInputs({*png}, inputs);
  }
  const TriangleMesh meshA = shapeOf(a, "distance: a"), meshB = shapeOf(b, "distance: b");
  SurfaceDistance d;
  {
    py::gil_scoped_release release;
    try {
      d = surfaceDistance(meshA, meshB, samples, seed);
    } catch (const DegenerateMesh& e) {
      const bool first = std::string(e.what()).find("first") != std::string::npos;
      throw std::invalid_argument(std::string(e.what()) + " (" + [&] {
        py::gil_scoped_acquire gil;
        return shapeName(first ? a : b);
      }() + ")");
    }
  }
  if (png) {
    const std::shared_ptr<const Sheet> sheet =
        py::isinstance<PyDesign>(a) ? snapshotOf(py::cast<const PyDesign&>(a))
                                    : std::make_shared<const Sheet>(meshSheet(meshA));
    py::gil_scoped_release release;
    HeadlessOptions options;
    options.width = 1280;
    options.height = 720;
    HeadlessRenderer renderer(options);
    std::vector<double> millimetres =
        pointDistances(sheet->positions, SurfaceDistanceQuery(meshB, "second"));
    double largest = 0.0;
    for (double& value : millimetres) largest = std::max(largest, value *= 1e3);
    const ColorLegend legend{ColorMap::Viridis, 0.0, std::max(largest, 1e-6), "distance to B",
                             "mm"};
    writeFileAtomically(*png, encodePng(renderFieldPicture(renderer, *sheet, millimetres, legend)));
  }
  return distanceDict(d);
}

// Design.fit's and curvefold.fit's limits, refused as the command line refuses them.
void checkFitLimits(std::size_t folds, std::optional<double> time,
                    std::optional<std::uint64_t> evaluations) {
  if (folds < 1 || folds > 64) throw std::invalid_argument("fit: folds must lie in 1 to 64");
  if (time && !(*time >= 0.1 && *time <= 86400.0))
    throw std::invalid_argument("fit: time must lie in 0.1 to 86400 seconds");
  if (evaluations && (*evaluations < 1 || *evaluations > 1'000'000'000'000ull))
    throw std::invalid_argument("fit: evaluations must lie in 1 to 10^12");
}

// A fit's report: where it ended, its steps, why it stopped and what it spent.
py::dict fitReport(const FitResult& result) {
  py::list steps;
  for (const FitProgress& step : result.steps) {
    py::dict item;
    item["folds"] = step.fold;
    item["hausdorff"] = step.hausdorff;
    item["chamfer"] = step.chamfer;
    item["seconds"] = step.seconds;
    steps.append(item);
  }
  const FitProgress& last = result.steps.back();
  py::dict report;
  report["folds"] = result.steps.size() - 1;
  report["hausdorff"] = last.hausdorff;
  report["chamfer"] = last.chamfer;
  report["diagonal"] = last.diagonal;
  report["steps"] = steps;
  report["stop"] = result.stopReason;
  report["timed_out"] = result.timedOut;
  report["out_of_evaluations"] = result.outOfEvaluations;
  report["evaluations"] = result.evaluations;
  report["dropped_samples"] = result.droppedSamples;
  return report;
}

// `curvefold fit TARGET --from <this design's surface>`, continuing from this design's folds:
// the search runs on a session of its own with the GIL released, and the folds it keeps are made
// on the design at the end, with the GIL held (the design never shows half a fit).
py::dict fitDesign(PyDesign& d, const py::object& target, std::size_t folds,
                   std::optional<double> time, std::uint64_t seed,
                   std::optional<std::uint64_t> evaluations, bool allowSelfIntersection) {
  checkFitLimits(folds, time, evaluations);
  const auto started = std::chrono::steady_clock::now();
  const std::string targetName = shapeName(target);
  TriangleMesh mesh = shapeOf(target, "fit: target");
  Design before;
  std::shared_ptr<const Sheet> initial;
  {
    DesignGuard guard(d);
    before = d.design(guard.lock);
    initial = std::make_shared<const Sheet>(d.session(guard.lock).initial());
  }
  FitResult result;
  {
    py::gil_scoped_release release;
    FitSettings settings;
    settings.seed = seed;
    settings.allowSelfIntersection = allowSelfIntersection;
    std::unique_ptr<FoldFitter> fitter;
    FoldSession session(*initial);
    if (!before.symmetry.empty()) session.setSymmetry(parseSymmetry(before.symmetry, *initial));
    session.applyRecords(before.folds);
    try {
      fitter = std::make_unique<FoldFitter>(std::move(mesh), settings);
      fitter->checkAgainst(session.fixed());
    } catch (const InvalidTarget& e) {
      throw std::invalid_argument(targetName + ": " + e.what());
    }
    FitOptions options;
    options.maxFolds = folds;
    // As the command line: evaluations alone use no clock.
    options.seconds = time ? *time : (evaluations ? std::numeric_limits<double>::infinity() : 60.0);
    options.started = started;
    options.maxEvaluations = evaluations.value_or(0);
    result = fitFolds(session, *fitter, options);
  }
  // The folds kept, made on the design (the same records: the same sheet).
  std::vector<FoldRecord> added(result.folds.begin() + std::ptrdiff_t(before.folds.size()),
                                result.folds.end());
  {
    DesignGuard guard(d);
    // Another thread's fold or undo meanwhile: the folds found continue a design that is gone.
    if (d.design(guard.lock).folds.size() != before.folds.size())
      throw std::runtime_error("fit: the design changed while it was fitted; fit it again");
    d.session(guard.lock).applyRecords(added);
  }
  return fitReport(result);
}

// `curvefold fit TARGET` (start None) or `curvefold fit TARGET --from KIND` (a catalogue name,
// sized to the target): the start chosen and revised as the command line chooses it
// (fit_start.hpp), folded with its runners-up and the nearer kept (runner_up_fits.hpp), with the
// GIL released. The kept design, and a report as Design.fit's with which start was kept and
// where every start's fit ended.
py::tuple fitTarget(const py::object& target, std::size_t folds, std::optional<double> time,
                    std::uint64_t seed, std::optional<std::uint64_t> evaluations,
                    std::optional<std::string> start, bool allowSelfIntersection) {
  checkFitLimits(folds, time, evaluations);
  const auto started = std::chrono::steady_clock::now();
  const double startedCpu = processCpuSeconds();
  const std::string kind = start.value_or("");
  if (!kind.empty()) {
    try {
      makeSurface(kind);  // an unknown name is refused as such, before the target is read
    } catch (const SurfaceError& e) {
      throw std::invalid_argument(std::string("fit: start: ") + e.what());
    }
  }
  const std::string targetName = shapeName(target);
  TriangleMesh mesh = shapeOf(target, "fit: target");
  Design design;
  RunnerUpFits fits;
  std::vector<RunnerUpStart> runnersUp;
  std::string ruleSurface;  // the rule's choice: its kind, and whether it was placed
  bool rulePlaced = false;
  {
    py::gil_scoped_release release;
    FitSettings settings;
    settings.seed = seed;
    settings.allowSelfIntersection = allowSelfIntersection;
    std::unique_ptr<FoldFitter> fitter;
    try {
      fitter = std::make_unique<FoldFitter>(std::move(mesh), settings);
    } catch (const InvalidTarget& e) {
      throw std::invalid_argument(targetName + ": " + e.what());
    }
    // As the command line: evaluations alone use no clock.
    const double seconds = time          ? *time
                           : evaluations ? std::numeric_limits<double>::infinity()
                                         : 60.0;
    FitStart chosen;
    try {
      chosen = chooseFitStart(*fitter, kind, std::nullopt,
                              FitStartClock{started, startedCpu, seconds, nullptr});
    } catch (const SurfaceError& e) {
      throw std::invalid_argument(std::string("fit: start: ") + e.what());
    }
    const StartChoice& choice = chosen.choice;
    ruleSurface = choice.surface;
    rulePlaced = choice.placed.has_value();
    if (choice.placed)
      design.surface = *choice.placed;
    else
      design.surface = GeneratedSurface{choice.surface, choice.parameters};
    FitOptions options;
    options.maxFolds = folds;
    options.seconds = seconds;
    options.started = started;
    options.maxEvaluations = evaluations.value_or(0);
    options.tubeChains = chosen.tubeChains;
    options.mayPlaceStart = true;  // chosen here, as `fit` without --from parameters
    runnersUp = choice.runnersUp;
    try {
      fits = fitWithRunnersUp(*fitter, initialSheet(design), "", runnersUp, options);
    } catch (const InvalidTarget& e) {
      throw std::invalid_argument(targetName + ": " + e.what());
    }
  }
  const std::size_t kept = fits.kept;
  if (kept > 0) {
    const RunnerUpStart& won = runnersUp[kept - 1];
    if (won.placed)
      design.surface = *won.placed;
    else
      design.surface = GeneratedSurface{won.surface, won.parameters};
  }
  const FitResult& result = fits.keptFit().result;
  if (result.placedStart) design.surface = *result.placedStart;  // the folds are made on it
  design.folds = result.folds;
  py::list starts;
  for (std::size_t i = 0; i < fits.fits.size(); ++i) {
    const FitProgress& ended = fits.fits[i].result.steps.back();
    py::dict item;
    item["surface"] = i == 0 ? ruleSurface : runnersUp[i - 1].surface;
    item["placed"] = i == 0 ? rulePlaced : runnersUp[i - 1].placed.has_value();
    item["hausdorff"] = ended.hausdorff;
    item["chamfer"] = ended.chamfer;
    item["kept"] = i == kept;
    starts.append(item);
  }
  py::dict report = fitReport(result);
  report["starts"] = starts;
  const std::string name = session::surfaceName(design);
  return py::make_tuple(PyDesign(std::move(design), name), report);
}

// The module's exceptions: ArgumentError, and the engine's one-line errors as Python's own.
void defineErrors(py::module_& m) {
  // An argument of the wrong type: both a ValueError (the module's rule: a bad argument is
  // ValueError naming its parameter) and a TypeError (Python's), one line either way. Kept for the
  // interpreter's life (a static py::object would be released after it ends).
  static PyObject* argumentError = [] {
    PyObject* bases = PyTuple_Pack(2, PyExc_ValueError, PyExc_TypeError);
    PyObject* type = PyErr_NewExceptionWithDoc(
        "curvefold.ArgumentError",
        "An argument of the wrong type, named in the message (a ValueError and a TypeError)", bases,
        nullptr);
    Py_XDECREF(bases);
    return type;
  }();
  if (!argumentError) throw py::error_already_set();
  m.attr("ArgumentError") = py::handle(argumentError);

  // The engine's one-line messages, as Python's own exceptions.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ArgumentTypeError& e) {
      PyErr_SetString(argumentError, e.what());
    } catch (const FileError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const DesignError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const ObjError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const InvalidSheet& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const CreasePatternError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const SimulationInputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const RecordingError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const VulkanError& e) {
      PyErr_SetString(PyExc_RuntimeError, e.what());
    }
  });
}

// What a fold and a check return.
void defineResults(py::module_& m) {
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
}

// Design's making and editing: new, from_obj, load, save, simulate, fold, undo, redo.
void defineDesignEditing(py::class_<PyDesign>& design) {
  design
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
          [](const py::object& pathArg) {
            const std::filesystem::path path = filePath(pathArg, "path");
            py::gil_scoped_release release;
            checkInputFile(path, kMaxDesignBytes, "design");
            return PyDesign(loadDesign(path), path.string(), path, true);
          },
          py::arg("path"), "Opens a design file (*.curvefold.json)")
      .def(
          "save",
          [](const PyDesign& d, const py::object& pathArg) {
            const std::filesystem::path path = filePath(pathArg, "path");
            d.checkOutput(path, "path", true);
            const Design whole = designOf(d);
            py::gil_scoped_release release;
            saveDesign(whole, path);
          },
          py::arg("path"), "Writes the design file atomically (the same bytes as the command line)")
      .def(
          "simulate",
          [](const PyDesign& d, const py::object& percent, const py::object& settle,
             const py::object& paper, const py::object& modulus, const py::object& contact,
             const py::object& steps, const py::object& stiffness, const py::object& motion,
             const py::object& pin, const py::object& glue) {
            return simulateDesign(
                d, {percent, settle, paper, modulus, contact, steps, stiffness, motion, pin, glue});
          },
          py::kw_only(), py::arg("percent") = 100.0, py::arg("settle") = true,
          py::arg("paper") = py::none(), py::arg("modulus") = py::none(), py::arg("contact") = true,
          py::arg("steps") = 2000, py::arg("stiffness") = py::none(), py::arg("motion") = false,
          py::arg("pin") = py::none(), py::arg("glue") = py::none(),
          "Folds the design's flat sheet to `percent` with the bar-and-hinge simulation, as "
          "`curvefold simulate DESIGN` does (the same state bit for bit): to equilibrium "
          "(settle=True, --settle) or by `steps` damped dynamic steps; paper=THICKNESS_MM for "
          "paper mode (--paper): modulus=GPA (default 4), self-contact keeping the layers the "
          "thickness apart unless contact=False (--no-contact); stiffness='curvefold' or "
          "'origami-simulator' (--stiffness, design mode); motion=True (--motion): targets along "
          "the sheet's folding motion; pin=[(x, y), ...] (--pin): hold the vertex nearest each "
          "flat-sheet point (metres); glue=[((x1, y1), (x2, y2)), ...] or 'slits' (--glue): pull "
          "the vertices nearest two points together, or glue every slit shut. Returns a dict as "
          "curvefold.simulate does (vertices numbered as the design's)")
      .def(
          "fold",
          [](PyDesign& d, const py::object& grab, const py::object& to) {
            const glm::dvec3 from = point3(grab, "grab"), drop = point3(to, "to");
            DesignGuard guard(d);
            return d.fold(guard.lock, from, drop);
          },
          py::kw_only(), py::arg("grab"), py::arg("to"),
          "Grabs the surface point nearest `grab` and drops it at `to`: the part holding it is "
          "reflected through their bisector plane (with its symmetric images)")
      .def(
          "undo",
          [](PyDesign& d) {
            DesignGuard guard(d);
            return d.session(guard.lock).undo();
          },
          "Takes the last fold (and its images) back; False when there is none")
      .def(
          "redo",
          [](PyDesign& d) {
            DesignGuard guard(d);
            return d.session(guard.lock).redo();
          },
          "Makes the last undone fold again; False when there is none");
}

// Design's reading and outputs: folds, surface, check, arrays, exports, fit, render.
void defineDesignReading(py::class_<PyDesign>& design) {
  design
      .def_property_readonly("folds", &foldsOf,
                             "The folds, each a dict: seed, plane_point, plane_normal, grabbed, "
                             "target, group")
      .def_property_readonly("symmetry", &PyDesign::symmetry, "'' or e.g. 'rotational:6:y'")
      .def_property_readonly(
          "surface", [](const PyDesign& d) { return session::surfaceName(designOf(d)); },
          "The surface's name, or 'embedded mesh'")
      .def(
          "check",
          [](const PyDesign& d, const py::object& allowArg) {
            const bool allowSelfIntersection = flag(allowArg, "allow_self_intersection");
            DesignGuard guard(d);
            return session::checkDesign(d.design(guard.lock), d.name(),
                                        d.session(guard.lock).initial(), *d.snapshot(guard.lock),
                                        allowSelfIntersection);
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
      .def("mesh", &meshArrays,
           "(vertices, triangles, development) of one state of the design, as the three "
           "properties give them; while another thread folds, separate reads of the properties "
           "may come from states either side of a fold")
      .def("creases", &creasesOf,
           "Crease edges: edges (k, 2) uint32, assignment ['M' or 'V'], angles (k,) degrees "
           "(FOLD's convention)")
      .def("to_fold", &foldDict, "The design as a FOLD dict (the FOLD file's content)")
      .def("export", &exportDesign, py::kw_only(), py::arg("fold") = py::none(),
           py::arg("svg") = py::none(), py::arg("obj") = py::none(), py::arg("gltf") = py::none(),
           py::arg("pdf") = py::none(), py::arg("cut_svg") = py::none(),
           py::arg("perforate") = py::none(), py::arg("paper") = "a4", py::arg("angles") = false,
           "Writes the named files, all or none (as `curvefold export`; the PDF's cover with the "
           "folded form and the date, a RuntimeWarning when there is no Vulkan device to draw it)")
      .def("fit", &fitDesign, py::arg("target"), py::kw_only(), py::arg("folds") = 6,
           py::arg("time") = py::none(), py::arg("seed") = 1, py::arg("evaluations") = py::none(),
           py::arg("allow_self_intersection") = false,
           "Folds the design toward a target shape (an OBJ path, a design file or a Design), as "
           "`curvefold fit` does from this design: at most `folds` more folds, each bringing it "
           "closer, within `time` seconds (default 60; none when only `evaluations` is given), "
           "scoring at most about `evaluations` candidate folds (the same seed then gives the "
           "same folds on any machine). Returns {folds, hausdorff, chamfer, diagonal (metres), "
           "steps, stop, timed_out, out_of_evaluations, evaluations, dropped_samples}; the design "
           "holds the "
           "folds kept.")
      .def("render", &renderDesign, py::arg("width") = 800, py::arg("height") = 600, py::kw_only(),
           py::arg("view") = "iso", py::arg("crease_pattern") = false,
           "The folded form as an (height, width, 4) uint8 RGBA image (headless Vulkan)")
      .def("__repr__", [](const PyDesign& d) {
        const Design whole = designOf(d);
        return "<curvefold.Design " + session::surfaceName(whole) + ", " +
               std::to_string(whole.folds.size()) + " folds" +
               (d.symmetry().empty() ? "" : ", " + d.symmetry()) + ">";
      });
}

// The module's functions: distance, simulate, surfaces, replay (and the benchmark's timer).
void defineFunctions(py::module_& m) {
  // For the overhead benchmark (python/bench/fold_overhead.py): the same fold as Design.fold,
  // timed in C++ without the binding, each taken back; seconds per fold.
  m.def(
      "_time_folds_in_cpp",
      [](PyDesign& d, const py::object& grab, const py::object& to, std::size_t repeats) {
        const glm::dvec3 from = point3(grab, "grab"), drop = point3(to, "to");
        std::vector<double> seconds;
        DesignGuard guard(d);
        for (std::size_t i = 0; i < repeats; ++i) {
          const auto start = std::chrono::steady_clock::now();
          const FoldResult result = d.fold(guard.lock, from, drop);
          seconds.push_back(
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
          if (result.folded) d.session(guard.lock).undo();
        }
        return seconds;
      },
      py::arg("design"), py::arg("grab"), py::arg("to"), py::arg("repeats"));
  m.def("fit", &fitTarget, py::arg("target"), py::kw_only(), py::arg("folds") = 6,
        py::arg("time") = py::none(), py::arg("seed") = 1, py::arg("evaluations") = py::none(),
        py::arg("start") = py::none(), py::arg("allow_self_intersection") = false,
        "Folds a sheet toward a target shape (an OBJ path, a design file or a Design) as "
        "`curvefold fit TARGET` does: start=None chooses and sizes the sheet as `fit` without "
        "--from, folds the rule's close runners-up too and keeps the design nearer by both "
        "measures; start='cone' (a catalogue name) sizes that kind, as --from cone. folds, time, "
        "seed and evaluations as Design.fit. Returns (Design, report): the report as "
        "Design.fit's, with starts: [{surface, placed, hausdorff, chamfer, kept}] for every start "
        "folded, the rule's choice first");
  m.def("distance", &distanceOf, py::arg("a"), py::arg("b"), py::kw_only(),
        py::arg("samples") = kDefaultDistanceSamples, py::arg("seed") = 1,
        py::arg("png") = py::none(),
        "How far two shapes (Designs, OBJ paths or design files) lie apart, as `curvefold "
        "distance A B`: {hausdorff, chamfer, diagonal (of b), hausdorff_relative, "
        "chamfer_relative, a_to_b_max, a_to_b_mean, b_to_a_max, b_to_a_mean}, metres; with "
        "png=PATH also a picture of a coloured by its distance to b (1280x720, legend in mm)");
  m.def(
      "simulate",
      [](const py::object& pattern, const py::object& percent, const py::object& settle,
         const py::object& paper, const py::object& modulus, const py::object& contact,
         const py::object& steps, const py::object& stiffness, const py::object& motion,
         const py::object& pin, const py::object& glue, const py::object& size) {
        return simulateCreasePattern(pattern, {percent, settle, paper, modulus, contact, steps,
                                               stiffness, motion, pin, glue, size});
      },
      py::arg("pattern"), py::kw_only(), py::arg("percent") = 100.0, py::arg("settle") = true,
      py::arg("paper") = py::none(), py::arg("modulus") = py::none(), py::arg("contact") = true,
      py::arg("steps") = 2000, py::arg("stiffness") = py::none(), py::arg("motion") = false,
      py::arg("pin") = py::none(), py::arg("glue") = py::none(), py::arg("size") = py::none(),
      "Folds a crease pattern from another tool (a FOLD dict as json.load gives it, or the path "
      "of a FOLD or SVG file in Origami Simulator's convention) with the bar-and-hinge "
      "simulation, as `curvefold simulate PATTERN` does (the same state bit for bit): from flat "
      "to `percent` of every crease's angle, to equilibrium (settle=True, --settle) or by "
      "`steps` damped dynamic steps; paper=THICKNESS_MM for paper mode (--paper): modulus=GPA "
      "(default 4), self-contact keeping the layers the thickness apart unless contact=False "
      "(--no-contact); stiffness='curvefold' or 'origami-simulator' (--stiffness, design "
      "mode); motion=True (--motion): targets along the pattern's folding motion (a "
      "waterbomb's); pin=[(x, y), ...] (--pin): hold the vertex nearest each flat-sheet point "
      "(metres, after size); glue=[((x1, y1), (x2, y2)), ...] (--glue): pull the vertices "
      "nearest two points together; size=MM (--size): the sheet's larger side in millimetres. "
      "Returns a dict: vertices (n, 3) and development (n, 2) (the pattern's flat vertices, "
      "after crossings are split, faces triangulated and cuts opened), triangles (m, 3), edges "
      "(e, 2), assignment (a str, one FOLD letter per edge), strain (e,), crease_angle_error "
      "(e,) in degrees, and what the command line prints of the state: largest_strain, "
      "largest_crease_angle_error and mean_crease_angle_error (degrees), wrong_side_creases, "
      "past_flat_creases, crossing_pairs (triangle pairs that cross), converged (settled), "
      "at_rounding_floor and rounding_floor (settled where the positions' rounding stops the "
      "residual above the tolerance, and that floor), iterations, energy_rises, residual, energy "
      "(with settle), motion (with motion=True: "
      "states, followed_to in percent, reached_full); and notes (what was read but not used)");
  m.def("surfaces", &surfacesInfo,
        "The catalogue: {name: {description, parameters: {name: {default, min, max, integer, "
        "description}}, symmetries}}");
  m.def(
      "replay",
      [](const py::object& recordingArg) {
        const std::filesystem::path recording = filePath(recordingArg, "recording");
        py::gil_scoped_release release;
        checkInputFile(recording);
        const ReplayResult result = studio::replayAnyRecording(readRecording(recording));
        return PyDesign(result.design, recording.string(), recording);
      },
      py::arg("recording"), "The design a recording (*.jsonl) makes, replayed headless");
}

}  // namespace
}  // namespace curvefold::python

PYBIND11_MODULE(_curvefold, m) {
  using namespace curvefold;
  using namespace curvefold::python;
  m.doc() = "curvefold: curved folding by reflection (the C++ engine)";

  // Now, at import, with the GIL held: pybind11 2.10's npy_api::get() (the first numpy array)
  // imports numpy inside a function-local static's initialisation guard, so two threads making
  // their first array at once deadlock, one holding the GIL and waiting on the guard, the other
  // holding the guard and waiting for the GIL (fixed upstream by gil_safe_call_once, pybind11
  // PR 4877, which Debian 12's pybind11 lacks).
  py::detail::npy_api::get();

  defineErrors(m);
  defineResults(m);
  py::class_<PyDesign> design(m, "Design",
                              "A design: an initial surface, its folds and a symmetry.");
  defineDesignEditing(design);
  defineDesignReading(design);
  defineFunctions(m);
}
