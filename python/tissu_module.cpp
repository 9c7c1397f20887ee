// tissu._tissu, the compiled half of the tissu Python package (python/tissu/__init__.py): a
// scenario, its cloth stepped frame by frame with the frame's arrays as NumPy arrays, and whole
// runs that write what the CLI writes. Errors become Python exceptions with the CLI's one-line
// messages: a scenario, mesh or pin refused is a ValueError, a step that diverges a
// tissu.SimulationError, a file the disk refuses an OSError. The GIL is released while stepping.

#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "lib/atomic_file.hpp"
#include "lib/scenario/scenario.hpp"
#include "lib/scenario/scenario_error.hpp"
#include "lib/simulation.hpp"
#include "lib/thread_count.hpp"
#include "topology/indexed_mesh.hpp"
#include "topology/pin_selection.hpp"

namespace py = pybind11;

namespace tissu {
namespace {

/// n x 3 float64 array of an interleaved 3n vector (a copy: the cloth's particles may change).
py::array_t<double> rows_of_three(const Eigen::VectorXd& xyz) {
  py::array_t<double> out({static_cast<py::ssize_t>(xyz.size() / 3), py::ssize_t{3}});
  std::copy(xyz.data(), xyz.data() + xyz.size(), out.mutable_data());
  return out;
}

py::array_t<double> rows_of_three(const std::vector<Eigen::Vector3d>& points) {
  py::array_t<double> out({static_cast<py::ssize_t>(points.size()), py::ssize_t{3}});
  double* x = out.mutable_data();
  for (const Eigen::Vector3d& p : points) x = std::copy(p.data(), p.data() + 3, x);
  return out;
}

/// t x 3 int32 triangles; a quad is split along its first diagonal, as frames.h5 does.
py::array_t<std::int32_t> triangles_of(const std::vector<std::vector<int>>& faces) {
  std::vector<std::int32_t> ids;
  for (const std::vector<int>& f : faces) {
    for (std::size_t k = 1; k + 1 < f.size(); ++k) ids.insert(ids.end(), {f[0], f[k], f[k + 1]});
  }
  py::array_t<std::int32_t> out({static_cast<py::ssize_t>(ids.size() / 3), py::ssize_t{3}});
  std::copy(ids.begin(), ids.end(), out.mutable_data());
  return out;
}

/// The frame's arrays as a dict of NumPy arrays, named as in frames.h5.
py::dict arrays_dict(const FrameArrays& a) {
  py::dict d;
  d["frame"] = a.frame;
  d["time_s"] = a.time_s;
  d["positions"] = rows_of_three(a.positions_m);
  d["velocities"] = rows_of_three(a.velocities_m_per_s);
  d["rest_positions"] = rows_of_three(a.rest_m);
  d["masses"] = py::array_t<double>(a.masses_kg.size(), a.masses_kg.data());
  d["triangles"] = triangles_of(a.faces);
  d["pinned"] = py::array_t<std::uint8_t>(a.pinned.size(), a.pinned.data());
  return d;
}

// the process's OpenMP threads set for a scenario's set-up, as `tissu run` sets them, then chosen
// before every frame (lib/thread_count.hpp), so that runs side by side (a parameter sweep) do not
// share cores; results do not depend on them
RunThreads threads_for_setup(const Scenario& scenario) {
  RunThreads threads;
  threads.before_setup(scenario.threads);
  return threads;
}

/// A Simulation with its thread choice (python.Simulation).
struct SteppedSimulation {
  explicit SteppedSimulation(const Scenario& scenario)
      : threads(threads_for_setup(scenario)), simulation(scenario) {}

  void step_frame() {
    threads.before_frame(simulation.particle_count());
    simulation.step_frame();
  }

  RunThreads threads;  // first: it sets the threads before the cloth is compiled
  Simulation simulation;
};

}  // namespace
}  // namespace tissu

PYBIND11_MODULE(_tissu, m) {
  using namespace tissu;
  m.doc() = "tissu's compiled core; use the tissu package (import tissu)";

  static py::exception<SimulationError> simulation_error(m, "SimulationError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ScenarioError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const MeshError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const PinError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const FileWriteError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const SimulationError& e) {
      simulation_error(e.what());
    }
  });

  py::class_<Scenario>(m, "Scenario", "A scenario as loaded: its settings, checked")
      .def_readonly("name", &Scenario::name)
      .def_readonly("frames", &Scenario::frames, "frames simulated after frame 0")
      .def_readonly("frame_rate", &Scenario::frame_rate, "frames per simulated second (Hz)")
      .def_readonly("substeps", &Scenario::substeps, "solver steps per frame")
      .def_readonly("notes", &Scenario::notes, "remarks from loading, one line each")
      .def_property_readonly(
          "resolved_json", [](const Scenario& s) { return s.resolved_json; },
          "the scenario as run, every default filled in (a run folder's scenario.json)");

  m.def(
      "load_scenario",
      [](const std::filesystem::path& file, const std::vector<std::string>& overrides) {
        return load_scenario(file, overrides);
      },
      py::arg("file"), py::arg("overrides") = std::vector<std::string>{},
      "Loads a scenario file with KEY=VALUE overrides (the CLI's --set)");

  py::class_<SteppedSimulation>(m, "Simulation", "A scenario's cloth stepped one frame at a time")
      .def(py::init<const Scenario&>(), py::arg("scenario"))
      .def("step", &SteppedSimulation::step_frame, py::call_guard<py::gil_scoped_release>(),
           "Advances one frame (the scenario's substeps)")
      .def_property_readonly("frame",
                             [](const SteppedSimulation& s) { return s.simulation.frame(); })
      .def(
          "arrays", [](const SteppedSimulation& s) { return arrays_dict(s.simulation.arrays()); },
          "The cloth now: a dict of NumPy arrays named as in frames.h5");

  m.def(
      "run",
      [](const Scenario& scenario, const std::filesystem::path& out, std::optional<int> frames,
         std::function<void(py::dict)> on_frame) {
        RunThreads threads = threads_for_setup(scenario);
        RunOptions options;
        options.output_dir = out;
        options.frames = frames;
        options.on_frame = [&on_frame, &threads](const FrameStats& row) {
          threads.before_frame(row.particles);
          if (on_frame) {
            py::gil_scoped_acquire gil;
            py::dict stats;
            for (const StatsColumn& c : stats_columns(row)) stats[c.name] = c.value;
            on_frame(stats);
          }
        };
        RunResult result;
        {
          py::gil_scoped_release released;
          result = run_scenario(scenario, options);
        }
        if (!result.ok) throw SimulationError(result.failure);
        py::dict d;
        d["frames_done"] = result.frames_done;
        d["unconverged_steps"] = result.unconverged_steps;
        d["images"] = result.images;
        d["video_warning"] = result.video_warning;
        return d;
      },
      py::arg("scenario"), py::arg("out"), py::arg("frames") = std::nullopt,
      py::arg("on_frame") = nullptr, "Runs a scenario as `tissu run` does, writing into `out`");
}
