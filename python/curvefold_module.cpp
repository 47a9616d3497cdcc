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
#include "app/guarded_design.hpp"
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

using session::FoldResult;
// The module's Design: safe to call from several Python threads at once (issue 40, 2).
using PyDesign = session::GuardedDesign;

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
  std::shared_ptr<const Sheet> sheet;
  Design whole;
  {
    DesignGuard guard(design);
    sheet = design.snapshot(guard.lock);
    whole = design.design(guard.lock);
  }
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

py::array_t<std::uint8_t> renderDesign(const PyDesign& design, std::uint32_t width,
                                       std::uint32_t height, const std::string& view,
                                       bool creasePattern) {
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
            const Design whole = designOf(d);
            py::gil_scoped_release release;
            saveDesign(whole, path);
          },
          py::arg("path"), "Writes the design file atomically (the same bytes as the command line)")
      .def(
          "fold",
          [](PyDesign& d, const std::vector<double>& grab, const std::vector<double>& to) {
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
          "Makes the last undone fold again; False when there is none")
      .def_property_readonly("folds", &foldsOf,
                             "The folds, each a dict: seed, plane_point, plane_normal, grabbed, "
                             "target, group")
      .def_property_readonly("symmetry", &PyDesign::symmetry, "'' or e.g. 'rotational:6:y'")
      .def_property_readonly(
          "surface", [](const PyDesign& d) { return session::surfaceName(designOf(d)); },
          "The surface's name, or 'embedded mesh'")
      .def(
          "check",
          [](const PyDesign& d, bool allowSelfIntersection) {
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
           "Writes the named files, all or none (as `curvefold export`)")
      .def("render", &renderDesign, py::arg("width") = 800, py::arg("height") = 600, py::kw_only(),
           py::arg("view") = "iso", py::arg("crease_pattern") = false,
           "The folded form as an (height, width, 4) uint8 RGBA image (headless Vulkan)")
      .def("__repr__", [](const PyDesign& d) {
        const Design whole = designOf(d);
        return "<curvefold.Design " + session::surfaceName(whole) + ", " +
               std::to_string(whole.folds.size()) + " folds" +
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
