// The Python module `medusa`: open a store, read its persistence diagrams as numpy arrays (GUDHI's
// and giotto-tda's layouts), its classes with the CompuCell3D cells that make them (docs/MATH.md §7.11),
// the complexes K(t) and the Betti curves; run the pipeline in-process (pipeline/python/README.md).
#include "cell_type.h"
#include "interrupt.h"
#include "python_run.h"
#include "python_store.h"
#include "ring_fate.h"

#include "medusa/core/error.h"
#include "medusa/medusa/complex_index.h"
#include "medusa/medusa/signatures.h"
#include "medusa/persistence/filtration.h"
#include "medusa/persistence/points.h"
#include "medusa/persistence/summaries.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <set>

namespace py = pybind11;

namespace medusa::python {
namespace {

persistence::Direction direction_of(const std::string& filtration) {
  if (filtration == "forward")
    return persistence::Direction::forward;
  if (filtration == "reverse")
    return persistence::Direction::reverse;
  throw InputError("filtration '" + filtration + "' is neither 'forward' nor 'reverse'");
}

// type=None or "all": the whole medusa; an int, or its decimal text, or the type's name: that cell
// type, as --type reads it (cell_type.h).
int type_of(const StoreView& store, const py::object& type) {
  if (type.is_none())
    return persistence::all_types;
  const std::string text =
      py::isinstance<py::str>(type) ? type.cast<std::string>() : std::to_string(type.cast<int>());
  return cli::resolve_cell_type(text, store.medusa().input, store.path());
}

py::array_t<double> rows_array(const std::vector<std::array<double, 3>>& rows, std::size_t columns) {
  py::array_t<double> out({rows.size(), columns});
  auto view = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = 0; j < columns; ++j)
      view(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(j)) = rows[i][j];
  return out;
}

// As the command line's --dim: a degree of the diagrams, 0 to 3 (a 3D medusa has H3).
void check_dim(std::optional<int> dim) {
  if (dim && (*dim < 0 || *dim > 3))
    throw InputError("dim=" + std::to_string(*dim) + " is not in range 0 to 3");
}

// Points in the stored order (degree, then birth filtration index): (birth, death, degree).
std::vector<std::array<double, 3>> points_of(const persistence::Diagram& d, std::optional<int> dim,
                                             bool zero_length) {
  std::vector<std::array<double, 3>> rows;
  for (const persistence::PersistencePair& p : d.pairs)
    if ((!dim || p.dim == *dim) && (zero_length || !p.zero_length))
      rows.push_back({p.birth, p.death, static_cast<double>(p.dim)});
  return rows;
}

py::object diagrams(StoreView& store, const py::object& type, std::optional<int> dim,
                    const std::string& filtration, bool zero_length, const std::string& layout) {
  check_dim(dim);
  const persistence::Diagram& d = store.diagram(direction_of(filtration), type_of(store, type));
  if (layout == "giotto")
    return rows_array(points_of(d, dim, zero_length), 3);
  if (layout != "gudhi")
    throw InputError("layout '" + layout + "' is neither 'gudhi' nor 'giotto'");
  if (dim)
    return rows_array(points_of(d, dim, zero_length), 2);
  py::dict by_degree;
  int top = -1;
  for (const persistence::PersistencePair& p : d.pairs)
    top = std::max(top, p.dim);
  for (int k = 0; k <= std::min(top, 3); ++k)
    by_degree[py::int_(k)] = rows_array(points_of(d, k, zero_length), 2);
  return std::move(by_degree);
}

py::object time_value(double t) { return py::float_(t); }

py::list classes(StoreView& store, const py::object& type, std::optional<int> dim,
                 const std::string& filtration, bool zero_length, bool shorten) {
  check_dim(dim);
  std::vector<std::string> wraps;
  const auto records =
      store.classes(direction_of(filtration), type_of(store, type), dim, zero_length, shorten, &wraps);
  py::list out;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const persistence::ClassRecord& r = records[i];
    py::dict c;
    c["id"] = r.id;
    c["dimension"] = r.dim;
    c["birth"] = time_value(r.birth);
    c["death"] = time_value(r.death);
    c["lifetime"] = time_value(r.lifetime());
    c["essential"] = r.essential;
    c["birth_kind"] = persistence::cell_kind_name(r.birth_kind);
    c["death_kind"] =
        r.essential ? py::object(py::none()) : py::object(py::str(persistence::cell_kind_name(r.death_kind)));
    c["birth_cells"] = r.birth_cells;
    c["death_cells"] = r.death_cells;
    c["cells"] = r.cells;
    c["medusa_birth_cell"] = r.birth_cell;
    c["medusa_death_cell"] = r.essential ? py::object(py::none()) : py::object(py::int_(r.death_cell));
    c["medusa_cycle"] = r.cycle;
    c["simplices"] = r.simplices;
    if (direction_of(filtration) == persistence::Direction::forward && r.essential && r.dim >= 1) {
      // As `medusa classes --format json`: what became of the representative's cells (ring_fate.h).
      const cli::RingFate fate = cli::ring_fate(store.medusa(), persistence::CellLists::List(r.cycle),
                                                store.medusa().cell(r.birth_cell).birth);
      py::dict ring;
      ring["state"] = cli::ring_state_name(fate.state);
      ring["broke_at"] = fate.state == cli::RingFate::State::broke ? py::object(py::float_(fate.broke_at))
                                                                   : py::object(py::none());
      c["ring"] = std::move(ring);
    }
    if (direction_of(filtration) == persistence::Direction::forward) {
      // As `medusa classes --format json`: the time seen in the tissue, null when never whole.
      const double seen = cli::time_seen(store.medusa(), r);
      c["seen"] = cli::never_whole(seen) ? py::object(py::none()) : py::object(py::float_(seen));
    }
    if (!wraps.empty()) // on a periodic run, as `medusa classes --format json` (docs/MATH.md §8.8)
      c["wraps"] = wraps[i];
    out.append(std::move(c));
  }
  return out;
}

// beta_k(s) = #{(b, d) : b <= s < d} of the filtration's diagram (docs/MATH.md §7.8), at the frame times
// by default; a reverse diagram is read on its -t axis, so beta_k(t) counts the classes of M_{>= t}.
py::tuple betti_curves(StoreView& store, const py::object& type, const std::string& filtration,
                       std::optional<std::vector<double>> times) {
  const persistence::Direction direction = direction_of(filtration);
  const persistence::Diagram& d = store.diagram(direction, type_of(store, type));
  std::vector<double> at;
  if (times)
    at = *times;
  else
    for (std::int64_t t : store.medusa().input.frame_times)
      at.push_back(static_cast<double>(t));
  for (double t : at)
    if (std::isnan(t))
      throw InputError("times holds nan: a Betti number is counted at a time");
  std::vector<double> axis = at;
  if (direction == persistence::Direction::reverse)
    for (double& s : axis)
      s = -s;
  constexpr std::size_t degrees = 4;
  py::array_t<std::int64_t> curves({degrees, at.size()});
  auto view = curves.mutable_unchecked<2>();
  for (std::size_t k = 0; k < degrees; ++k) {
    const std::vector<std::size_t> beta =
        persistence::betti_curve(persistence::to_points(d, static_cast<int>(k)), axis);
    for (std::size_t i = 0; i < at.size(); ++i)
      view(static_cast<py::ssize_t>(k), static_cast<py::ssize_t>(i)) = static_cast<std::int64_t>(beta[i]);
  }
  return py::make_tuple(py::array_t<double>(at.size(), at.data()), curves);
}

// The Betti numbers of the time slices K_t at the frames (docs/MATH.md §6.6; K(t_end-) at the last), as
// `medusa curves --frames-only` gives them: the clusters, loops and cavities a picture of frame k shows.
// Not the Betti curves of the time filtration (betti_curves), which count classes of M_{<= t}.
py::tuple slices(StoreView& store, const py::object& type) {
  const int id = type_of(store, type);
  const std::optional<int> only = id == persistence::all_types ? std::nullopt : std::optional<int>(id);
  const medusa::Medusa& m = store.medusa();
  const std::size_t frames = m.input.frames();
  std::vector<medusa::Signature> at(frames);
  {
    py::gil_scoped_release release;
    for (std::size_t k = 0; k < frames; ++k)
      at[k] = medusa::signature_of(m, medusa::cells_at_frame(m, k, only));
  }
  constexpr std::size_t degrees = 4;
  py::array_t<std::int64_t> betti({degrees, frames});
  auto view = betti.mutable_unchecked<2>();
  for (std::size_t k = 0; k < degrees; ++k)
    for (std::size_t i = 0; i < frames; ++i)
      view(static_cast<py::ssize_t>(k), static_cast<py::ssize_t>(i)) =
          static_cast<std::int64_t>(at[i].betti[k]);
  std::vector<double> times;
  for (std::int64_t t : m.input.frame_times)
    times.push_back(static_cast<double>(t));
  return py::make_tuple(py::array_t<double>(times.size(), times.data()), betti);
}

// The run's cell types with their names ("" where the run names none).
py::dict type_names(const StoreView& store) {
  py::dict out;
  const auto& names = store.medusa().input.type_names;
  for (int t : store.types())
    out[py::int_(t)] = static_cast<std::size_t>(t) < names.size() ? names[static_cast<std::size_t>(t)] : "";
  return out;
}

// <medusa.Store 'run.h5': 251 cells of types 1 (Condensing), 2 (NonCondensing), 21 frames, MCS 0 to 2000>
std::string store_repr(const StoreView& store) {
  const auto& input = store.medusa().input;
  std::string types;
  for (int t : store.types()) {
    const std::string name = static_cast<std::size_t>(t) < input.type_names.size()
                                 ? input.type_names[static_cast<std::size_t>(t)]
                                 : "";
    types += (types.empty() ? "" : ", ") + std::to_string(t) + (name.empty() ? "" : " (" + name + ")");
  }
  std::set<std::int64_t> cells;
  for (const auto& c : input.cells)
    cells.insert(c.cell_id);
  return "<medusa.Store '" + store.path() + "': " + std::to_string(cells.size()) + " cells of types " +
         types + ", " + std::to_string(input.frames()) + " frames" +
         (input.frame_times.empty() ? std::string()
                                    : ", MCS " + std::to_string(input.frame_times.front()) + " to " +
                                          std::to_string(input.frame_times.back())) +
         ">";
}

std::shared_ptr<StoreView> open_store(const std::string& path) {
  py::gil_scoped_release release;
  return std::make_shared<StoreView>(path);
}

// Ctrl-C during medusa.run: Python's own SIGINT handler only sets a flag while the GIL is released,
// so the pipeline's interrupt hook asks the interpreter (at most every 50 ms) to run its pending
// signal handlers. The exception a handler raised (KeyboardInterrupt by default) is kept here while
// the pipeline unwinds, removing its temporary store, and raised again when medusa.run returns.
struct PendingSignal {
  PyObject* type = nullptr;
  PyObject* value = nullptr;
  PyObject* traceback = nullptr;
};
PendingSignal pending_signal; // guarded by the GIL

bool python_signal_raised() {
  using clock = std::chrono::steady_clock;
  static thread_local clock::time_point next{};
  const clock::time_point now = clock::now();
  if (now < next)
    return false;
  next = now + std::chrono::milliseconds(50);
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() == 0)
    return false;
  PyErr_Fetch(&pending_signal.type, &pending_signal.value, &pending_signal.traceback);
  return true;
}

// Installs the hook for the duration of one medusa.run.
class SignalHook {
public:
  SignalHook() { medusa::cli::set_interrupt_hook(&python_signal_raised); }
  ~SignalHook() { medusa::cli::set_interrupt_hook(nullptr); }
  SignalHook(const SignalHook&) = delete;
  SignalHook& operator=(const SignalHook&) = delete;
};

std::shared_ptr<StoreView> run(const std::string& input, const py::object& radius, const std::string& output,
                               const std::string& source, bool snap, unsigned threads, bool force,
                               bool shorten_representatives, bool periodic_as_open, bool round_csv,
                               bool skip_unreadable_frames) {
  RunRequest request;
  request.input = input;
  request.radius =
      py::isinstance<py::str>(radius) ? radius.cast<std::string>() : py::str(radius).cast<std::string>();
  request.output = output;
  request.source = source;
  request.snap = snap;
  request.threads = threads;
  request.force = force;
  request.shorten_representatives = shorten_representatives;
  request.periodic_as_open = periodic_as_open;
  request.round_csv = round_csv;
  request.skip_unreadable_frames = skip_unreadable_frames;
  std::shared_ptr<StoreView> store;
  {
    const SignalHook hook;
    py::gil_scoped_release release;
    const std::string path =
        run_pipeline(request, "medusa.run(" + input + ", radius=" + request.radius + ") [python]");
    store = std::make_shared<StoreView>(path);
  }
  // What `medusa run` prints on stderr as warnings (later frames missing, snapshots left out), as
  // Python warnings; the store records them too (Store.input_warnings).
  for (const std::string& w : store->medusa().run.input_warnings)
    if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) < 0)
      throw py::error_already_set();
  return store;
}

} // namespace
} // namespace medusa::python

PYBIND11_MODULE(medusa, m) {
  using namespace medusa::python;
  m.doc() =
      "medusa: exact topology of CompuCell3D cell-sorting runs (docs/MATH.md); see pipeline/python/README.md";
  auto error = py::register_exception<medusa::Error>(m, "Error", PyExc_RuntimeError);
  error.attr("__doc__") =
      "What medusa refuses or cannot do (bad input, a corrupt store, geometry outside the "
      "method), as one line: the message `medusa` prints before its exit code";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p)
        std::rethrow_exception(p);
    } catch (const medusa::cli::Interrupted&) {
      if (pending_signal.type != nullptr)
        PyErr_Restore(pending_signal.type, pending_signal.value, pending_signal.traceback);
      else
        PyErr_SetNone(PyExc_KeyboardInterrupt);
      pending_signal = PendingSignal{};
    }
  });

  py::class_<StoreView, std::shared_ptr<StoreView>>(m, "Store", "A medusa store (run.h5) read into memory")
      .def_property_readonly("path", &StoreView::path, "the store's path, as opened")
      .def_property_readonly("types", &StoreView::types, "the cell types of the run (CompuCell3D type ids)")
      .def("__repr__", &store_repr)
      .def_property_readonly("type_names", &type_names,
                             "the cell types of the run with their names, {1: 'Condensing', ...} (\"\" where "
                             "the run names none), as `medusa info` lists them")
      .def_property_readonly(
          "frame_times", [](const StoreView& s) { return s.medusa().input.frame_times; },
          "the frame times (MCS)")
      .def_property_readonly(
          "input_warnings", [](const StoreView& s) { return s.medusa().run.input_warnings; },
          "what reading the input warned of, one line each as `medusa run` printed it (later frames "
          "missing, snapshots left out, ...; [] if nothing, and for stores written before it was recorded)")
      .def_property_readonly(
          "periodic_axes", [](const StoreView& s) { return s.medusa().run.periodic_axes; },
          "the periodic axes of the run (\"x,y\", ...; \"\" for an open run, docs/MATH.md §8)")
      .def("diagrams", &diagrams, py::arg("type") = py::none(), py::arg("dim") = py::none(),
           py::arg("filtration") = "forward", py::arg("zero_length") = false, py::arg("layout") = "gudhi",
           "Persistence diagram of the whole medusa (type None or 'all') or of one cell type (its id or "
           "name).\n"
           "layout='gudhi': with dim, an (n, 2) array of (birth, death); without, a dict degree -> such "
           "an array. layout='giotto': an (n, 3) array of (birth, death, degree). Essential classes have "
           "death inf (forward) or -inf (reverse, whose births are >= deaths: docs/MATH.md §7.3).")
      .def("classes", &classes, py::arg("type") = py::none(), py::arg("dim") = py::none(),
           py::arg("filtration") = "forward", py::arg("zero_length") = false, py::arg("shorten") = false,
           "The classes with their representatives (docs/MATH.md §7.11), one dict each, in diagram order; "
           "the keys of `medusa classes --format json`. shorten=True: shortened representatives, as "
           "`medusa classes --shorten` (docs/MATH.md §7.13).")
      .def(
          "K_at",
          [](const StoreView& s, double t, const py::object& type) {
            const int id = type_of(s, type);
            const std::optional<int> only =
                id == medusa::persistence::all_types ? std::nullopt : std::optional<int>(id);
            py::gil_scoped_release release;
            return s.complex_at(t, only);
          },
          py::arg("t"), py::arg("type") = py::none(),
          "The alpha complex K(t+) as a list of simplices, each a sorted list of CC3D cell ids; with type "
          "(an id or name), of that cell type's subcomplex")
      .def(
          "betti_curves", &betti_curves, py::arg("type") = py::none(), py::arg("filtration") = "forward",
          py::arg("times") = py::none(),
          "(times, curves): curves[k][i] = number of degree-k classes alive at times[i] in the filtration "
          "(docs/MATH.md §7.8), at the frame times by default. These count classes of the time filtration "
          "M_{<= t} (a cluster that split off later is still one class); the clusters, loops and cavities of "
          "the complex K_t at each frame, as `medusa curves` counts them, are slices()")
      .def("slices", &slices, py::arg("type") = py::none(),
           "(times, betti): betti[k][i] = b_k of the complex K_t at frame i (docs/MATH.md §6.6; K(t_end-) at "
           "the last frame), the numbers of clusters (k=0), loops (1) and cavities (2) of `medusa curves "
           "--frames-only`, of the whole complex or of one cell type (id or name)");

  m.def("open", &open_store, py::arg("path"), "Open a store written by `medusa run` or medusa.run");
  m.def("run", &run, py::arg("input"), py::arg("radius") = "auto", py::arg("output") = "",
        py::arg("source") = "", py::arg("snap") = true, py::arg("threads") = 0, py::arg("force") = false,
        py::arg("shorten_representatives") = false, py::arg("periodic_as_open") = false,
        py::arg("round_csv") = false, py::arg("skip_unreadable_frames") = false,
        "Run the pipeline of `medusa run` in this process (the GIL is released) on a CC3D output folder "
        "or cells.csv[.gz], write the store (default <input name>.h5; an existing one only with force=True) "
        "and return it opened. Ctrl-C stops it with KeyboardInterrupt and leaves no store. A periodic run "
        "is analysed on the torus (docs/MATH.md §8). snap=False refuses VTK centroids off the grid, as "
        "`--exact-vtk` (by default they are snapped and that is recorded, as by `medusa run`); "
        "shorten_representatives, periodic_as_open, round_csv, skip_unreadable_frames: as `medusa run "
        "--shorten-representatives` (docs/MATH.md §7.13), `--periodic-as-open`, `--round-csv` and "
        "`--skip-unreadable-frames`.");
}
