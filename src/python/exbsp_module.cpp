// SPDX-License-Identifier: LGPL-3.0-or-later
// The Python module `exbsp` (pybind11, numpy arrays in and out); docs/python.md is its manual.
//
// Notation: a mesh is (vertices, faces[, face_ids]): vertices an (n, 3) float64 array (the
// exact input, docs/contract.md "Input"); faces an (m, k >= 3) integer array or a list of polygons,
// fan-triangulated, face id = row index unless face_ids gives one per row. Exact coordinates
// come out as fractions.Fraction, parsed from the engine's reduced "p/q" text.
// Errors: exbsp::usage_error -> exbsp.UsageError (a ValueError), input_error -> exbsp.InputError
// (a ValueError, with .file and .line), limit_error -> exbsp.LimitError (a MemoryError), any
// other exbsp::error -> exbsp.Error; an exception raised by a Python score callback propagates
// unchanged. The GIL is released while the engine runs and taken back for each callback.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <exbsp/bsp/distributed.h>
#include <exbsp/bsp/engine.h>
#include <exbsp/clip/section.h>
#include <exbsp/clip/section_cap.h>
#include <exbsp/core/errors.h>
#include <exbsp/core/version.h>
#include <exbsp/mesh/mesh_io.h>
#include <exbsp/view/png_io.h>
#include <exbsp/view/render.h>
#include "core/atomic_file.h"
#include "core/file_name.h"
#include "drawing/drawing.h"
#include "scene/drawing_command.h"

namespace py = pybind11;

namespace {

using exbsp::usage_error;

/// True while the interpreter shuts down. A callback from a build in a daemon thread must not
/// take the GIL then: Python ends such threads with pthread_exit, whose unwinding through the
/// engine's frames aborts the process ("FATAL: exception not rethrown"). The build is
/// cancelled instead (the C++ exception unwinds normally; nobody is left to see it).
bool interpreter_finalizing() {
#if PY_VERSION_HEX >= 0x030D0000
  return Py_IsFinalizing() != 0;
#else
  return _Py_IsFinalizing() != 0;
#endif
}

/// Calls into the engine in progress (they run without the GIL), and whether the interpreter is
/// exiting. A thread that takes the GIL back while the interpreter finalizes is ended by
/// pthread_exit, whose unwinding through the engine (or an OpenMP region) aborts the process:
/// at exit (an atexit hook, before finalization) no new call starts, builds are cancelled at
/// their next callback, and the interpreter waits until every call has left the engine.
std::atomic<int> calls_in_engine{0};
std::atomic<bool> shutting_down{false};

/// Counts one call into the engine; refuses new calls once the interpreter exits.
class counted_call {
 public:
  counted_call() {
    if (shutting_down.load()) throw exbsp::build_cancelled("the interpreter is exiting");
    calls_in_engine.fetch_add(1);
  }
  ~counted_call() { calls_in_engine.fetch_sub(1); }
  counted_call(const counted_call&) = delete;
  counted_call& operator=(const counted_call&) = delete;
};

/// A call into the engine: counted, with the GIL released for its lifetime (taken back before
/// the count drops, so that a thread the exit hook waited for is back in Python).
class engine_call {
 public:
  engine_call() = default;

 private:
  counted_call count_;
  py::gil_scoped_release release_;
};

/// The exit hook (registered with atexit): stops new calls, cancels builds, waits (up to a
/// minute) for the calls in progress to return.
void finish_engine_calls() {
  shutting_down.store(true);
  py::gil_scoped_release release;
  for (int k = 0; k < 60000 && calls_in_engine.load() > 0; ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

/// Raises build_cancelled in a build callback (which holds the GIL) once the interpreter exits.
void check_not_exiting() {
  if (shutting_down.load() || interpreter_finalizing())
    throw exbsp::build_cancelled("the interpreter is exiting");
}

/// A path argument: str or os.PathLike, without NUL (a C string would be cut there).
std::string path_argument(const py::handle& h, const std::string& what) {
  py::object p = py::module_::import("os").attr("fspath")(h);
  if (!py::isinstance<py::str>(p)) throw usage_error(what + ": expected a str path, got bytes");
  const std::string s = p.cast<std::string>();
  if (s.empty()) throw usage_error(what + ": empty path");
  if (s.find('\0') != std::string::npos) throw usage_error(what + ": the path contains a NUL byte");
  return s;
}

/// The value of a Python integer or numpy integer (not a float); `what` names it in messages.
long long integer(py::handle h, const std::string& what) {
  PyObject* as_index = PyNumber_Index(h.ptr());
  if (!as_index) {
    PyErr_Clear();
    throw usage_error(what + " is not an integer");
  }
  const long long v = PyLong_AsLongLong(as_index);
  Py_DECREF(as_index);
  if (v == -1 && PyErr_Occurred()) {
    PyErr_Clear();
    throw usage_error(what + " is out of range");
  }
  return v;
}

/// faces[i][j] = v checked as an index into vertex_count vertices.
std::uint32_t vertex_index(long long v, std::size_t i, std::size_t j, std::size_t vertex_count) {
  if (v < 0 || static_cast<unsigned long long>(v) >= vertex_count)
    throw usage_error("faces[" + std::to_string(i) + "][" + std::to_string(j) +
                      "] = " + std::to_string(v) + " is not a vertex index (" +
                      std::to_string(vertex_count) + " vertices)");
  return static_cast<std::uint32_t>(v);
}
std::uint32_t vertex_index(py::handle h, std::size_t i, std::size_t j, std::size_t vertex_count) {
  return vertex_index(integer(h, "faces[" + std::to_string(i) + "][" + std::to_string(j) + "]"), i,
                      j, vertex_count);
}

/// A soup from numpy/sequence input (see the notation above). Throws usage_error naming the
/// offending argument for shapes, non-integer or out-of-range indices and short polygons.
exbsp::triangle_soup soup_from(
    const py::array_t<double, py::array::c_style | py::array::forcecast>& vertices,
    const py::object& faces, const py::object& face_ids) {
  exbsp::triangle_soup soup;
  soup.source = "<python>";
  if (vertices.size() != 0 && (vertices.ndim() != 2 || vertices.shape(1) != 3))
    throw usage_error("vertices must be an (n, 3) array of float64");
  const auto n = static_cast<std::size_t>(vertices.size() / 3);
  const double* v = vertices.data();
  soup.vertices.resize(n);
  for (std::size_t i = 0; i < n; ++i) soup.vertices[i] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};

  // Rows of `faces`: a 2-D integer array, or any sequence of sequences (polygons).
  std::vector<std::vector<std::uint32_t>> polygons;
  const bool is_array = py::isinstance<py::array>(faces);
  if (is_array &&
      py::reinterpret_borrow<py::array>(faces).size() != 0) {  // fast path: the integers directly
    const auto a = py::reinterpret_borrow<py::array>(faces);
    const char kind = a.dtype().kind();
    if (kind != 'i' && kind != 'u')
      throw usage_error("faces must be an integer array (got dtype " +
                        std::string(py::str(a.dtype())) + ")");
    if (a.ndim() != 2 || a.shape(1) < 3)
      throw usage_error("faces must be an (m, k) array with k >= 3");
    // The converting constructor, not array_t::ensure: ensure clears the Python error of a
    // failed conversion (a MemoryError for a large array), leaving nothing to raise.
    const py::array_t<long long, py::array::c_style | py::array::forcecast> rows(a);
    const auto m = static_cast<std::size_t>(rows.shape(0)),
               k = static_cast<std::size_t>(rows.shape(1));
    polygons.assign(m, std::vector<std::uint32_t>(k));
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t j = 0; j < k; ++j)
        polygons[i][j] = vertex_index(rows.data()[i * k + j], i, j, n);
  }
  std::size_t i = 0;
  if (!is_array)
    for (py::handle row : py::iter(faces)) {
      if (!py::isinstance<py::sequence>(row))
        throw usage_error("faces[" + std::to_string(i) + "] is not a sequence of vertex indices");
      std::vector<std::uint32_t> polygon;
      std::size_t j = 0;
      for (py::handle index : py::iter(row)) polygon.push_back(vertex_index(index, i, j++, n));
      if (polygon.size() < 3)
        throw usage_error("faces[" + std::to_string(i) + "] has " + std::to_string(polygon.size()) +
                          " vertices (a face needs at least 3)");
      polygons.push_back(std::move(polygon));
      ++i;
    }
  std::vector<std::uint32_t> ids;
  if (!face_ids.is_none()) {
    std::size_t k = 0;
    for (py::handle id : py::iter(face_ids)) {
      const long long value = integer(id, "face_ids[" + std::to_string(k) + "]");
      if (value < 0 || value > 0xfffffffeLL)
        throw usage_error("face_ids[" + std::to_string(k) + "] = " + std::to_string(value) +
                          " is not a face id");
      ids.push_back(static_cast<std::uint32_t>(value));
      ++k;
    }
    if (ids.size() != polygons.size())
      throw usage_error("face_ids has " + std::to_string(ids.size()) + " entries for " +
                        std::to_string(polygons.size()) + " faces");
  }
  for (std::size_t f = 0; f < polygons.size(); ++f)
    soup.add_polygon(polygons[f], ids.empty() ? static_cast<std::uint32_t>(f) : ids[f]);
  return soup;
}

/// fractions.Fraction of the engine's "p/q" text.
py::object fraction(const std::string& text) {
  static const auto* fraction_type =
      new py::object(py::module_::import("fractions").attr("Fraction"));
  return (*fraction_type)(text);
}

py::tuple exact_point(const std::array<std::string, 3>& p) {
  return py::make_tuple(fraction(p[0]), fraction(p[1]), fraction(p[2]));
}

py::dict stats_dict(const exbsp::build_stats& s) {
  py::dict d;
  exbsp::for_each_stat(s, [&d](const char* name, const auto& value) { d[name] = value; });
  return d;
}

/// A numpy array of `shape` (row-major) with element j = at(j).
template <class T, class At>
py::array_t<T> make_array(std::vector<py::ssize_t> shape, const At& at) {
  py::array_t<T> out(shape);
  T* p = out.mutable_data();
  for (py::ssize_t j = 0; j < out.size(); ++j) p[j] = at(static_cast<std::size_t>(j));
  return out;
}

template <class T>
py::array_t<T> to_numpy(const std::vector<T>& v) {
  return make_array<T>({static_cast<py::ssize_t>(v.size())}, [&](std::size_t j) { return v[j]; });
}

/// (n, 3) uint32 corner indices and (n,) face ids of section or soup triangles.
template <class Triangle, class Corners>
std::pair<py::array_t<std::uint32_t>, py::array_t<std::uint32_t>> triangle_arrays(
    const std::vector<Triangle>& ts, Corners corners) {
  const auto n = static_cast<py::ssize_t>(ts.size());
  return {
      make_array<std::uint32_t>({n, 3}, [&](std::size_t j) { return (ts[j / 3].*corners)[j % 3]; }),
      make_array<std::uint32_t>({n}, [&](std::size_t j) { return ts[j].face; })};
}

/// The options exbsp.build and exbsp.plan_build share (docs/python.md).
void set_common_options(exbsp::build_options& o, std::uint64_t seed,
                        const std::array<unsigned, 3>& sampled, std::size_t max_fragments) {
  o.seed = seed;
  o.max_fragments = max_fragments;
  o.sampled_candidates = sampled[0];
  o.sampled_samples = sampled[1];
  o.sampled_split_weight = sampled[2];
}

/// The coordinator of a distributed build (exbsp/bsp/distributed.h) as Python sees it.
struct distributed_plan {
  std::unique_ptr<exbsp::distributed_build> build;

  exbsp::distributed_build& get() {
    if (!build) throw usage_error("DistributedBuild: finish() was already called");
    return *build;
  }
};

distributed_plan plan_build(
    const py::array_t<double, py::array::c_style | py::array::forcecast>& vertices,
    const py::object& faces, const std::optional<std::string>& heuristic, std::uint64_t seed,
    const std::array<unsigned, 3>& sampled, std::size_t max_fragments, const py::object& face_ids) {
  const exbsp::triangle_soup soup = soup_from(vertices, faces, face_ids);
  exbsp::build_options o;
  o.heuristic = heuristic ? *heuristic : exbsp::default_heuristic();
  set_common_options(o, seed, sampled, max_fragments);
  engine_call no_gil;
  distributed_plan plan;
  plan.build = std::make_unique<exbsp::distributed_build>(soup, o);
  return plan;
}

/// exbsp.build: see docs/python.md.
exbsp::bsp build(const py::array_t<double, py::array::c_style | py::array::forcecast>& vertices,
                 const py::object& faces, const std::string& kernel,
                 const std::optional<std::string>& heuristic, std::uint64_t seed,
                 const py::object& score, const std::string& candidates,
                 const std::array<unsigned, 3>& sampled, std::optional<unsigned> threads,
                 std::size_t max_fragments, const py::object& face_ids) {
  const exbsp::triangle_soup soup = soup_from(vertices, faces, face_ids);
  exbsp::build_options o;
  o.kernel = exbsp::parse_kernel(kernel);
  o.heuristic = heuristic ? *heuristic : score.is_none() ? exbsp::default_heuristic() : "custom";
  set_common_options(o, seed, sampled, max_fragments);
  // A Python score runs under the GIL: on other threads each call also makes and drops a
  // Python thread state (5x slower on 2 threads than on 1, measured), so one thread by default.
  o.threads = threads ? *threads : score.is_none() ? 0u : 1u;
  if (candidates == "all")
    o.score_candidates = exbsp::candidate_set::all;
  else if (candidates == "sampled")
    o.score_candidates = exbsp::candidate_set::sampled;
  else
    throw usage_error("candidates must be 'all' or 'sampled' (got '" + candidates + "')");
  if (!score.is_none()) {
    if (!PyCallable_Check(score.ptr())) throw usage_error("score must be callable");
    // Called from the build's threads without the GIL: take it for each call.
    o.score = [score](const exbsp::candidate_score_input& in) {
      if (interpreter_finalizing()) throw exbsp::build_cancelled();
      py::gil_scoped_acquire gil;
      check_not_exiting();
      const py::object result = score(in);
      const double value = PyFloat_AsDouble(result.ptr());  // a number (TypeError for "1.5")
      if (value == -1.0 && PyErr_Occurred()) throw py::error_already_set();
      return value;
    };
  }
  // Ctrl-C: the engine reports progress about every 256 nodes, one call at a time from any of
  // its threads; on the calls that come on this (the main) thread a pending signal raises
  // KeyboardInterrupt and the build stops (PyErr_CheckSignals does nothing on other threads).
  o.progress = [](const exbsp::build_progress&) {
    if (interpreter_finalizing()) throw exbsp::build_cancelled();
    py::gil_scoped_acquire gil;
    check_not_exiting();
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  };
  engine_call no_gil;
  return exbsp::bsp::build(soup, o);
}

/// The Tree behind `self`. pybind11 hands a method the storage of an instance that was never
/// constructed (exbsp.Tree.__new__(exbsp.Tree), or one whose __setstate__ failed) as if it
/// held a tree, and using it crashes the interpreter: every method of Tree takes `self` and
/// checks here first (TypeError instead).
const exbsp::bsp& tree_of(py::handle self) {
  if (!py::isinstance<exbsp::bsp>(self))
    throw py::type_error("expected an exbsp.Tree, got " + std::string(py::str(self.get_type())));
  auto* inst = reinterpret_cast<py::detail::instance*>(self.ptr());
  const auto vh = inst->get_value_and_holder(py::detail::get_type_info(typeid(exbsp::bsp)), false);
  if (!vh || !vh.holder_constructed() || !vh.value_ptr())
    throw py::type_error(
        "this exbsp.Tree was never initialised (trees come from exbsp.build, exbsp.load, "
        "exbsp.deserialize or pickle)");
  return *static_cast<const exbsp::bsp*>(vh.value_ptr());
}

std::size_t checked_index(const exbsp::bsp& t, py::ssize_t i) {
  const auto n = static_cast<py::ssize_t>(t.fragment_count());
  if (i < -n || i >= n)
    throw py::index_error("fragment index " + std::to_string(i) + " out of range (" +
                          std::to_string(n) + " fragments)");
  return static_cast<std::size_t>(i < 0 ? i + n : i);
}

/// exbsp.section: see docs/python.md.
py::dict section(const py::array_t<double, py::array::c_style | py::array::forcecast>& vertices,
                 const py::object& faces, const std::array<double, 4>& plane, bool cap, bool exact,
                 const py::object& face_ids) {
  const exbsp::triangle_soup soup = soup_from(vertices, faces, face_ids);
  exbsp::section_options options;
  options.exact_text = exact;
  exbsp::section_result r;
  {
    engine_call no_gil;
    r = cap ? exbsp::section_with_cap(soup, plane, options) : exbsp::section(soup, plane, options);
  }
  const auto points = make_array<double>({static_cast<py::ssize_t>(r.points.size()), 3},
                                         [&](std::size_t j) { return r.points[j / 3].v[j % 3]; });
  py::dict d;
  d["plane"] = py::make_tuple(plane[0], plane[1], plane[2], plane[3]);
  d["closed"] = r.closed;
  d["points"] = points;
  if (exact) {
    py::list ex;
    for (const auto& pt : r.points) ex.append(exact_point(pt.exact));
    d["exact"] = ex;
  }
  const auto kept = triangle_arrays(r.kept, &exbsp::section_triangle::p);
  d["kept"] = kept.first;
  d["kept_faces"] = kept.second;
  py::list outline;
  for (const auto& c : r.outline) {
    py::dict chain;
    chain["closed"] = c.closed;
    chain["points"] = to_numpy(c.p);
    outline.append(chain);
  }
  d["outline"] = outline;
  d["cap"] = triangle_arrays(r.cap, &exbsp::section_triangle::p).first;
  d["cap_face"] = r.cap_face;
  py::dict s;
  exbsp::for_each_section_stat(r, [&](const char* name, auto value) { s[name] = value; });
  d["stats"] = s;
  return d;
}

/// exbsp.read_mesh: (vertices (n, 3) float64, triangles (t, 3) uint32, face_ids (t,) uint32).
py::tuple read_mesh(const py::object& path_object) {
  const std::string path = path_argument(path_object, "path");
  exbsp::triangle_soup soup;
  {
    engine_call no_gil;
    soup = exbsp::read_mesh(path);
  }
  const auto v = make_array<double>({static_cast<py::ssize_t>(soup.vertices.size()), 3},
                                    [&](std::size_t j) { return soup.vertices[j / 3][j % 3]; });
  const auto t = triangle_arrays(soup.triangles, &exbsp::soup_triangle::v);
  return py::make_tuple(v, t.first, t.second);
}

/// A Python exception class named exbsp.NAME deriving from `bases` (a tuple), added to `m`.
py::handle new_exception(py::module_& m, const char* name, const py::tuple& bases,
                         const char* doc) {
  const std::string full = std::string("exbsp.") + name;
  py::object type = py::reinterpret_steal<py::object>(
      PyErr_NewExceptionWithDoc(full.c_str(), doc, bases.ptr(), nullptr));
  if (!type) throw py::error_already_set();
  m.attr(name) = type;
  return type;  // m keeps a reference
}

/// A list of strings from a str ("a,b") or a sequence of str.
std::vector<std::string> string_list(const py::handle& h) {
  if (py::isinstance<py::str>(h)) {
    std::vector<std::string> out;
    std::string item;
    for (char c : h.cast<std::string>() + ",") {
      if (c != ',') {
        item += c;
      } else if (!item.empty()) {
        out.push_back(item);
        item.clear();
      }
    }
    return out;
  }
  return h.cast<std::vector<std::string>>();
}

/// exbsp.drawing: one sheet of a mesh or scene file, written to each of `outputs`.
py::dict drawing(const py::object& input, const py::object& outputs, const py::object& views,
                 const std::string& projection, const std::string& sheet, const std::string& scale,
                 const std::string& units, const std::string& up, const py::object& sections,
                 bool lines_only, const std::string& title, const std::string& number,
                 const std::string& date, std::array<double, 2> line_widths, double crease_deg,
                 const std::string& kernel) {
  namespace dr = exbsp::drawing;
  const std::string in = path_argument(input, "input");
  std::vector<std::string> outs;
  if (py::isinstance<py::str>(outputs) || py::hasattr(outputs, "__fspath__"))
    outs.push_back(path_argument(outputs, "outputs"));
  else
    for (const py::handle o : outputs) outs.push_back(path_argument(o, "outputs"));
  if (outs.empty()) throw usage_error("outputs: at least one .svg, .pdf or .dxf file");
  std::vector<std::string> formats;
  for (const std::string& o : outs) {
    std::string f;
    for (const char* e : {"svg", "pdf", "dxf"})
      if (exbsp::has_extension(o, std::string(".") + e)) f = e;
    if (f.empty()) throw usage_error("outputs: " + o + " does not end in .svg, .pdf or .dxf");
    formats.push_back(f);
  }
  dr::drawing_options o;
  std::string view_text;
  for (const std::string& v : string_list(views)) view_text += (view_text.empty() ? "" : ",") + v;
  o.views = dr::parse_views(view_text, "views");
  o.projection = dr::parse_projection(projection, "projection");
  o.sheet = dr::parse_paper(sheet, "sheet");
  if (scale != "auto") o.scale = dr::parse_scale(scale, "scale");
  dr::unit_mm(units, "units");
  o.units = units;
  if (up != "z" && up != "y") throw usage_error("up: expected 'z' or 'y', got '" + up + "'");
  o.up = up;
  for (const std::string& s : string_list(sections))
    o.sections.push_back(dr::parse_section(s, "sections"));
  o.lines_only = lines_only;
  o.title = title;
  o.number = number;
  o.date = date.empty() ? dr::today_date() : date;
  o.visible_width = line_widths[0];
  o.hidden_width = line_widths[1];
  if (!(crease_deg > 0 && crease_deg <= 180)) throw usage_error("crease_deg: must be in (0, 180]");
  o.crease_deg = crease_deg;
  o.build.kernel = exbsp::parse_kernel(kernel);
  // For a scene, its "drawing" block gives what the call leaves at the defaults.
  const dr::drawing_options defaults;
  std::vector<std::string> given;
  if (!title.empty()) given.push_back("title");
  if (!number.empty()) given.push_back("number");
  if (!date.empty()) given.push_back("date");
  if (o.views != defaults.views) given.push_back("views");
  if (o.projection != defaults.projection) given.push_back("projection");
  if (sheet != defaults.sheet.name) given.push_back("sheet");
  if (scale != "auto") given.push_back("scale");
  if (units != defaults.units) given.push_back("units");
  if (up != defaults.up) given.push_back("up");
  if (!o.sections.empty()) given.push_back("sections");
  if (lines_only) given.push_back("lines_only");
  if (o.visible_width != defaults.visible_width || o.hidden_width != defaults.hidden_width)
    given.push_back("line_widths");
  if (crease_deg != defaults.crease_deg) given.push_back("crease_deg");
  if (date.empty()) o.date.clear();
  const bool dxf_only =
      std::all_of(formats.begin(), formats.end(), [](const std::string& f) { return f == "dxf"; });
  if (dxf_only) {
    o = exbsp::scene::lines_only_if(o, true);
    given.push_back("lines_only");
  }
  std::size_t triangles = 0;
  dr::drawing_options used;
  {
    engine_call release;
    const dr::sheet s =
        exbsp::scene::make_drawing_sheet(in, o, false, nullptr, &triangles, &given, &used);
    for (std::size_t k = 0; k < outs.size(); ++k)
      exbsp::write_file_atomically(outs[k], exbsp::scene::drawing_bytes(s, formats[k], used));
  }
  py::dict r;
  r["written"] = outs;
  r["triangles"] = triangles;
  r["date"] = used.date;
  return r;
}

}  // namespace

/// Tree.render: the tree seen by a fitted view of its input (`view`) or by a camera at `eye`
/// looking at `look_at`; an image (h, w, 3) uint8 array, PNG bytes or SVG text.
py::object render_tree(const exbsp::bsp& tree, int width, int height, const std::string& view,
                       const std::optional<exbsp::vec3d>& eye,
                       const std::optional<exbsp::vec3d>& look_at, const exbsp::vec3d& up,
                       double fovy_deg, const std::string& format,
                       const std::optional<std::string>& edges, const std::array<int, 3>& color,
                       const std::array<int, 3>& background) {
  namespace v = exbsp::view;
  if (format != "image" && format != "png" && format != "svg")
    throw usage_error("render: format must be 'image', 'png' or 'svg', got '" + format + "'");
  const auto rgb = [](const std::array<int, 3>& c, const char* name) {
    for (int x : c)
      if (x < 0 || x > 255)
        throw usage_error(std::string("render: ") + name + " channels must be in 0..255");
    return v::rgb8{static_cast<std::uint8_t>(c[0]), static_cast<std::uint8_t>(c[1]),
                   static_cast<std::uint8_t>(c[2])};
  };
  const v::render_style style{rgb(color, "color"), rgb(background, "background")};
  if (eye.has_value() != look_at.has_value())
    throw usage_error("render: give both eye=(x, y, z) and look_at=(x, y, z), or neither");
  std::string svg;
  v::image picture;
  {
    engine_call no_gil;
    const v::fitted_view fitted =
        eye ? v::view_of_tree(
                  tree, {v::to_point(*eye), v::to_point(*look_at), v::vector3{up[0], up[1], up[2]}},
                  fovy_deg)
            : v::fit_view(tree.input(), width, height, view);
    // Edges by default: visible ones in an SVG (a line drawing), none over a picture.
    if (format == "svg")
      svg = v::render_tree_svg(tree, fitted, width, height, style, edges.value_or("visible"));
    else
      picture = v::render_tree(tree, fitted, width, height, style, edges.value_or("none"));
  }
  if (format == "svg") return py::str(svg);
  if (format == "png") {
    std::vector<std::uint8_t> bytes;
    {
      engine_call no_gil;
      bytes = v::encode_png(picture);
    }
    return py::bytes(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  }
  const auto& data = picture.data();
  return make_array<std::uint8_t>({picture.height(), picture.width(), 3},
                                  [&](std::size_t j) { return data[j]; });
}

PYBIND11_MODULE(_exbsp, m) {
  m.doc() = "Exact-predicate BSP trees and exact sections of triangle meshes (see docs/python.md).";
  m.attr("__version__") = exbsp::version_string;
  m.attr("version") = exbsp::version_string;
  m.attr("HEURISTICS") = py::tuple(py::cast(exbsp::heuristic_names()));
  m.attr("KERNELS") = py::tuple(py::cast(exbsp::kernel_names()));
  m.attr("DEFAULT_HEURISTIC") = exbsp::default_heuristic();
  py::module_::import("atexit").attr("register")(py::cpp_function(&finish_engine_calls));

  // Exception classes; the translator keeps them alive for the module's lifetime.
  // Handles, not objects: no Py_DECREF after the interpreter has finalized (the module holds them).
  static py::handle error_type, usage_type, input_type, limit_type, output_type;
  error_type = new_exception(m, "Error", py::make_tuple(py::handle(PyExc_Exception)),
                             "Base of exbsp's errors.");
  // Each of the others derives from Error and the Python exception of the same meaning.
  struct derived {
    py::handle* type;
    const char* name;
    PyObject* python_base;
    const char* doc;
  };
  for (const derived& d :
       {derived{&usage_type, "UsageError", PyExc_ValueError,
                "A bad argument: shape, index, name, non-finite coordinate."},
        derived{&input_type, "InputError", PyExc_ValueError,
                "A bad mesh file; .file and .line (0: none) name the place."},
        derived{&limit_type, "LimitError", PyExc_MemoryError,
                "A resource limit (max_fragments) was reached; nothing is returned."},
        derived{&output_type, "OutputError", PyExc_OSError,
                "A file could not be written (Tree.save); nothing partial is left."}})
    *d.type =
        new_exception(m, d.name, py::make_tuple(error_type, py::handle(d.python_base)), d.doc);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const exbsp::input_error& e) {
      py::object err = input_type(e.what());  // an instance carrying .file and .line
      err.attr("file") = e.file();
      err.attr("line") = e.line();
      PyErr_SetObject(input_type.ptr(), err.ptr());
    } catch (const exbsp::usage_error& e) {
      PyErr_SetString(usage_type.ptr(), e.what());
    } catch (const exbsp::limit_error& e) {
      PyErr_SetString(limit_type.ptr(), e.what());
    } catch (const exbsp::output_error& e) {
      PyErr_SetString(output_type.ptr(), e.what());
    } catch (const exbsp::error& e) {
      PyErr_SetString(error_type.ptr(), e.what());
    }
  });

  py::class_<exbsp::candidate_score_input>(
      m, "Candidate", "What a score callback sees for one candidate splitter at one node.")
      .def_readonly("candidate", &exbsp::candidate_score_input::candidate,
                    "position in the node's list")
      .def_readonly("face", &exbsp::candidate_score_input::face, "its face id")
      .def_readonly("source", &exbsp::candidate_score_input::source,
                    "its input triangle (whose plane it is)")
      .def_readonly("positive", &exbsp::candidate_score_input::positive)
      .def_readonly("negative", &exbsp::candidate_score_input::negative)
      .def_readonly("straddling", &exbsp::candidate_score_input::straddling,
                    "fragments the plane would split")
      .def_readonly("coplanar", &exbsp::candidate_score_input::coplanar)
      .def_readonly("list_size", &exbsp::candidate_score_input::list_size)
      .def_readonly("depth", &exbsp::candidate_score_input::depth, "the node's depth (root: 1)")
      .def("__repr__", [](const exbsp::candidate_score_input& c) {
        return "Candidate(candidate=" + std::to_string(c.candidate) +
               ", face=" + std::to_string(c.face) + ", positive=" + std::to_string(c.positive) +
               ", negative=" + std::to_string(c.negative) +
               ", straddling=" + std::to_string(c.straddling) +
               ", coplanar=" + std::to_string(c.coplanar) +
               ", list_size=" + std::to_string(c.list_size) + ", depth=" + std::to_string(c.depth) +
               ")";
      });

  py::class_<exbsp::bsp>(
      m, "Tree", "A built BSP tree (exbsp.build). Immutable; safe to share between threads.")
      .def_property_readonly("stats",
                             [](py::handle self) { return stats_dict(tree_of(self).stats()); })
      .def_property_readonly(
          "kernel", [](py::handle self) { return exbsp::to_string(tree_of(self).kernel()); })
      .def("__len__", [](py::handle self) { return tree_of(self).fragment_count(); })
      .def(
          "order",
          [](py::handle self, const std::optional<exbsp::vec3d>& eye,
             const std::optional<exbsp::vec3d>& direction, bool back_to_front) {
            const exbsp::bsp& t = tree_of(self);
            if (eye.has_value() == direction.has_value())
              throw usage_error("order: give exactly one of eye=(x, y, z) or direction=(x, y, z)");
            std::vector<std::uint32_t> order;
            {
              engine_call no_gil;
              order = eye ? t.order_from_eye(*eye, back_to_front)
                          : t.order_for_direction(*direction, back_to_front);
            }
            return to_numpy(order);
          },
          py::kw_only(), py::arg("eye") = py::none(), py::arg("direction") = py::none(),
          py::arg("back_to_front") = true,
          "Fragment indices (uint32 array) back to front, or front to back, for a perspective "
          "view from eye=(x, y, z) or a parallel view along direction=(x, y, z) (from the eye "
          "into the scene): paint fragments() in this order. Exact: the same order on every "
          "machine. Give exactly one of eye and direction.")
      .def(
          "fragments",
          [](py::handle self) {
            const exbsp::bsp& t = tree_of(self);
            const std::vector<exbsp::fragment_d> f = t.fragments_double();
            const auto n = static_cast<py::ssize_t>(f.size());
            const auto v = make_array<double>(
                {n, 3, 3}, [&](std::size_t j) { return f[j / 9].v[j / 3 % 3][j % 3]; });
            const auto faces =
                make_array<std::uint32_t>({n}, [&](std::size_t j) { return f[j].face; });
            return py::make_tuple(v, faces);
          },
          "(vertices (k, 3, 3) float64, face ids (k,) uint32) of the fragments in storage order.")
      .def(
          "exact",
          [](py::handle self, py::ssize_t i) {
            const exbsp::bsp& t = tree_of(self);
            const exbsp::exact_triangle e = t.fragment_exact(checked_index(t, i));
            return py::make_tuple(exact_point(e[0]), exact_point(e[1]), exact_point(e[2]));
          },
          py::arg("i"), "Fragment i's corners as ((Fraction,) * 3,) * 3 (exact kernels only).")
      .def(
          "ancestors",
          [](py::handle self, py::ssize_t i) {
            const exbsp::bsp& t = tree_of(self);
            py::list out;
            for (const auto& a : t.ancestors(checked_index(t, i)))
              out.append(py::make_tuple(a.plane_face, a.side));
            return out;
          },
          py::arg("i"), "[(input triangle whose plane it is, side +1/-1), ...] from the root down.")
      .def(
          "inserted",
          [](py::handle self,
             const py::array_t<double, py::array::c_style | py::array::forcecast>& vertices,
             const py::object& faces, std::size_t max_fragments, const py::object& face_ids) {
            const exbsp::bsp& t = tree_of(self);
            const exbsp::triangle_soup added = soup_from(vertices, faces, face_ids);
            exbsp::insert_options o;
            o.max_fragments = max_fragments;
            engine_call no_gil;
            return t.inserted(added, o);
          },
          py::arg("vertices"), py::arg("faces"), py::kw_only(), py::arg("max_fragments") = 0,
          py::arg("face_ids") = py::none(),
          "A new Tree: this naive tree (heuristic='naive') with the mesh (vertices, faces; as "
          "exbsp.build takes them) inserted, exactly the tree exbsp.build makes with "
          "heuristic='naive' of this tree's input followed by the new triangles (face ids "
          "continue after this tree's: the new ones are shifted by its face count). This tree "
          "is left as it is. UsageError for a tree built with another heuristic or bad input, "
          "LimitError beyond max_fragments (0: no limit). The GIL is released while it works.")
      .def(
          "save",
          [](py::handle self, const py::object& path) {
            const exbsp::bsp& t = tree_of(self);
            const std::string p = path_argument(path, "path");
            engine_call no_gil;
            t.save(p);
          },
          py::arg("path"),
          "Writes the tree to a file (docs/tree-file.md); exbsp.load reads it back.")
      .def(
          "serialize",
          [](py::handle self, bool reproducible) {
            const exbsp::bsp& t = tree_of(self);
            return py::bytes(reproducible ? t.serialize_reproducible() : t.serialize());
          },
          py::kw_only(), py::arg("reproducible") = false,
          "The bytes save writes; reproducible=True writes the two measured stats "
          "(build_seconds, peak_rss_bytes) as 0, so that equal trees give equal bytes (a "
          "distributed build and a local one, two runs, two machines).")
      .def(
          "render",
          [](py::handle self, int width, int height, const std::string& view,
             const std::optional<exbsp::vec3d>& eye, const std::optional<exbsp::vec3d>& look_at,
             const exbsp::vec3d& up, double fovy_deg, const std::string& format,
             const std::optional<std::string>& edges, const std::array<int, 3>& color,
             const std::array<int, 3>& background) {
            return render_tree(tree_of(self), width, height, view, eye, look_at, up, fovy_deg,
                               format, edges, color, background);
          },
          py::kw_only(), py::arg("width") = 800, py::arg("height") = 600, py::arg("view") = "iso",
          py::arg("eye") = py::none(), py::arg("look_at") = py::none(),
          py::arg("up") = exbsp::vec3d{0, 1, 0}, py::arg("fovy_deg") = 30.0,
          py::arg("format") = "image", py::arg("edges") = py::none(),
          py::arg("color") = std::array<int, 3>{176, 190, 214},
          py::arg("background") = std::array<int, 3>{250, 250, 252},
          "The tree painted back to front (painter's algorithm, flat light from over the "
          "viewer's shoulder), seen by the fitted view `view` of its input (iso, front, back, "
          "left, right, top, bottom: the view `exbsp render MESH --view` uses) or by a "
          "perspective camera at `eye` looking at `look_at` (with `up`, `fovy_deg`). format "
          "'image': a (height, width, 3) uint8 array, top row first; 'png': PNG bytes; 'svg': "
          "the SVG text. `edges` 'none', 'visible' or 'visible+hidden': the feature edges with "
          "exact visibility, hidden ones dashed (default: 'visible' in an SVG, 'none' over an "
          "image or PNG, where they are drawn over the shaded faces).")
      .def(py::pickle([](py::handle self) { return py::bytes(tree_of(self).serialize()); },
                      [](const py::bytes& b) {
                        return exbsp::bsp::deserialize(std::string(b), "<pickled exbsp.Tree>");
                      }));

  py::class_<distributed_plan>(
      m, "DistributedBuild",
      "The coordinator of a distributed build (exbsp.plan_build): the top of the tree, grown "
      "here, and its frontier cells for the workers (exbsp.build_cell).")
      .def_property_readonly(
          "input", [](distributed_plan& p) { return py::bytes(p.get().input()); },
          "The bytes every worker needs besides its cell: the soup and the options.")
      .def_property_readonly(
          "cells",
          [](distributed_plan& p) {
            py::list out;
            for (std::size_t i = 0; i < p.get().cell_count(); ++i)
              out.append(py::bytes(p.get().cell(i)));
            return out;
          },
          "The frontier cells' bytes, in frontier order (at most 16; none when the top holds "
          "the whole tree).")
      .def(
          "add_part",
          [](distributed_plan& p, std::size_t i, const py::bytes& part) {
            std::string bytes(part);
            exbsp::distributed_build& b = p.get();
            engine_call no_gil;
            b.add_part(i, std::move(bytes));
          },
          py::arg("i"), py::arg("part"),
          "Adds the part exbsp.build_cell made from cells[i] (any order, each once).")
      .def(
          "finish",
          [](distributed_plan& p) {
            exbsp::distributed_build& b = p.get();
            std::optional<exbsp::bsp> tree;
            {
              engine_call no_gil;
              tree = b.finish();
            }
            p.build.reset();
            return std::move(*tree);
          },
          "The Tree, once every part is in: the tree exbsp.build makes (byte-identical "
          "serialize(reproducible=True)). InputError for a malformed or mismatched part.");
  m.def("plan_build", &plan_build, py::arg("vertices"), py::arg("faces"), py::kw_only(),
        py::arg("heuristic") = py::none(), py::arg("seed") = 0,
        py::arg("sampled") = std::array<unsigned, 3>{16, 512, 8}, py::arg("max_fragments") = 0,
        py::arg("face_ids") = py::none(),
        "Grows the top levels of exbsp.build(vertices, faces, ...) (exact kernel; named "
        "heuristics only) and returns a DistributedBuild whose cells any worker can grow with "
        "exbsp.build_cell. exbsp.build_distributed runs the whole build on a Dask cluster.");
  m.def(
      "build_cell",
      [](const py::bytes& input, const py::bytes& cell) {
        const std::string in(input), c(cell);
        std::string part;
        {
          engine_call no_gil;
          part = exbsp::distributed_build::build_cell(in, c);
        }
        return py::bytes(part);
      },
      py::arg("input"), py::arg("cell"),
      "A worker's job: the subtree of one cell (DistributedBuild.cells[i]) for the build's "
      "input (DistributedBuild.input), as bytes for DistributedBuild.add_part. Depends on the "
      "bytes only; InputError for malformed bytes.");

  m.def("build", &build, py::arg("vertices"), py::arg("faces"), py::kw_only(),
        py::arg("kernel") = "exact", py::arg("heuristic") = py::none(), py::arg("seed") = 0,
        py::arg("score") = py::none(), py::arg("candidates") = "all",
        py::arg("sampled") = std::array<unsigned, 3>{16, 512, 8}, py::arg("threads") = py::none(),
        py::arg("max_fragments") = 0, py::arg("face_ids") = py::none(),
        R"doc(Builds the exact BSP tree of a mesh.

vertices: (n, 3) float64 (anything numpy converts); the doubles are the exact input.
faces: (m, k) integer array (k >= 3) or a list of polygons of any lengths; polygons are
    fan-triangulated from their first vertex.
kernel: 'exact' (default), 'epeck' or 'gmpq' (the same tree, exactly), 'epick' or 'double'
    (rounded split points: to see what rounding does).
heuristic: one of HEURISTICS ('naive', 'min-split', 'sampled', 'random'); None: the default
    ('sampled'), or 'custom' when `score` is given.
seed: seed of the randomised heuristics; the same seed gives the same tree everywhere.
score: a function Candidate -> float; the lowest score splits each node (ties to the earliest
    candidate). Called from the build's threads: it must depend on its input only.
candidates: 'all' (every fragment, counted over the node's list) or 'sampled' (the sampled
    heuristic's candidates, counted on its sample), for `score`.
sampled: (candidates, samples, split_weight) of the sampled heuristic (16, 512, 8).
threads: worker threads (0: all cores); None: all cores, or one when `score` is given.
max_fragments: raise LimitError beyond this many fragments (0: no limit).
face_ids: (m,) face id of each row of `faces` (default: the row), e.g. read_mesh's third array.

Returns a Tree. Raises UsageError (bad argument) or LimitError; degenerate triangles are
skipped and counted in tree.stats['degenerate_input']. The GIL is released while it builds.
See docs/python.md.)doc");
  m.def("section", &section, py::arg("vertices"), py::arg("faces"), py::arg("plane"), py::kw_only(),
        py::arg("cap") = true, py::arg("exact") = true, py::arg("face_ids") = py::none(),
        "Cuts a mesh exactly by the plane A*x + B*y + C*z + D = 0 (plane=(A, B, C, D)), keeping "
        "the side where it is >= 0. Returns a dict: points (p, 3) float64, exact (p points as "
        "Fractions, when exact=True), kept (q, 3) indices with kept_faces, outline (loops and "
        "chains of point indices), cap (closed input, when cap=True) with cap_face, closed, "
        "plane, stats. See "
        "docs/python.md.");
  m.def(
      "load",
      [](const py::object& path) {
        const std::string p = path_argument(path, "path");
        engine_call no_gil;
        return exbsp::bsp::load(p);
      },
      py::arg("path"),
      "Reads a tree saved by Tree.save or `exbsp build --save` (InputError when it is bad).");
  m.def(
      "deserialize",
      [](const py::bytes& b) { return exbsp::bsp::deserialize(std::string(b), "<bytes>"); },
      py::arg("data"), "A tree from the bytes Tree.serialize returns.");
  m.def("read_mesh", &read_mesh, py::arg("path"),
        "Reads an OFF/OBJ/PLY/STL file: (vertices, triangles, face_ids).");
  m.def("drawing", &drawing, py::arg("input"), py::arg("outputs"), py::kw_only(),
        py::arg("views") = std::vector<std::string>{"front", "top", "left", "iso"},
        py::arg("projection") = "first-angle", py::arg("sheet") = "A3", py::arg("scale") = "auto",
        py::arg("units") = "mm", py::arg("up") = "z",
        py::arg("sections") = std::vector<std::string>{}, py::arg("lines_only") = false,
        py::arg("title") = "", py::arg("number") = "", py::arg("date") = "",
        py::arg("line_widths") = std::array<double, 2>{0.5, 0.25}, py::arg("crease_deg") = 30.0,
        py::arg("kernel") = "exact",
        "One drawing sheet (`exbsp drawing`) of a mesh or scene file, written to each of "
        "`outputs` (.svg, .pdf, .dxf); see docs/python.md. Returns {'written', 'triangles', "
        "'date'}.");
  m.def("today_date", &exbsp::drawing::today_date,
        "Today's date (UTC, YYYY-MM-DD), or SOURCE_DATE_EPOCH's: the date sheets carry.");
}
