// The Python module `candela`: candela.render(), candela.bench(), candela.load(), candela.Scene, candela.Error, over
// libcandela's public interface (include/candela). docs/python.md shows it in use.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "candela/candela.h"
#include "image_arrays.h"
#include "scene_bindings.h"

namespace py = pybind11;
namespace api = candela::api;
using candela::python::arrayOf;

namespace {

// What the callback of candela.render() receives. It reads the render's film only during the callback: kept
// beyond it, image() raises candela.Error instead of reading a film that is gone.
struct RenderProgress {
  uint32_t samples = 0, samplesPerPixel = 0;
  double seconds = 0.0;
  const api::Progress* live = nullptr;

  py::array_t<float> image() const {
    if (!live) throw api::Error("a render's progress can be read only during its callback");
    api::Image image;
    {
      py::gil_scoped_release release;
      image = live->image();
    }
    return arrayOf(image);
  }
};

// A path, a built-in name, a candela.Scene or a candela.LoadedScene, as a scene to render.
api::Scene sceneOf(const py::object& scene) {
  if (py::isinstance<api::Scene>(scene)) return scene.cast<api::Scene>();
  // Built with the GIL held: another thread must not add to the builder meanwhile.
  if (py::isinstance<api::SceneBuilder>(scene)) return scene.cast<const api::SceneBuilder&>().build();
  if (!py::isinstance<py::str>(scene) && !py::hasattr(scene, "__fspath__"))
    throw py::type_error("scene: a path, a built-in scene's name, a candela.Scene or a candela.LoadedScene");
  const std::string spec = py::module_::import("os").attr("fspath")(scene).cast<std::string>();
  py::gil_scoped_release release;
  return api::Scene::load(spec);
}

api::RenderOptions optionsOf(std::optional<uint32_t> width, std::optional<uint32_t> height, std::optional<uint32_t> spp,
                             const std::string& backend, uint32_t seed, std::optional<uint32_t> maxDepth,
                             const std::optional<std::string>& denoise, const std::vector<std::string>& aovs,
                             const std::optional<std::string>& shading, uint32_t threads) {
  api::RenderOptions options;
  options.width = width;
  options.height = height;
  options.samplesPerPixel = spp;
  options.backend = backend;
  options.seed = seed;
  options.maxDepth = maxDepth;
  options.denoiser = denoise.value_or("none");
  options.aovs = aovs;
  options.shading = shading.value_or("");
  options.threads = threads;
  return options;
}

// Renders with the GIL released. After each sample per pixel the GIL is taken back briefly: to call `callback`
// (whose False ends the render) and to let Ctrl-C stop the render with KeyboardInterrupt. An exception of the
// callback's ends the render and is raised from render().
api::RenderResult renderReleasingTheGil(const api::Scene& scene, const api::RenderOptions& options,
                                        const py::object& callback) {
  std::exception_ptr failure;
  auto progress = [&](const api::Progress& p) {
    py::gil_scoped_acquire gil;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (callback.is_none()) return true;
      py::object state = py::cast(RenderProgress{p.samples, p.samplesPerPixel, p.seconds, &p});
      // However the callback ends, the film is not read through `state` afterwards (a traceback may keep it).
      struct Expiry {
        RenderProgress& progress;
        ~Expiry() { progress.live = nullptr; }
      } expiry{state.cast<RenderProgress&>()};
      const py::object answer = callback(state);
      return answer.ptr() != Py_False;
    } catch (...) {
      failure = std::current_exception();
      return false;
    }
  };
  api::RenderResult result;
  {
    py::gil_scoped_release release;
    result = api::render(scene, options, progress);
  }
  if (failure) std::rethrow_exception(failure);
  return result;
}

py::object render(const py::object& scene, std::optional<uint32_t> width, std::optional<uint32_t> height,
                  std::optional<uint32_t> spp, const std::string& backend, uint32_t seed,
                  std::optional<uint32_t> maxDepth, const std::optional<std::string>& denoise,
                  const std::vector<std::string>& aovs, const py::object& callback,
                  const std::optional<std::string>& shading, uint32_t threads) {
  const api::RenderOptions options =
      optionsOf(width, height, spp, backend, seed, maxDepth, denoise, aovs, shading, threads);
  const api::RenderResult result = renderReleasingTheGil(sceneOf(scene), options, callback);
  py::array_t<float> image = arrayOf(result.image);
  if (aovs.empty()) return image;
  py::dict planes;
  for (const auto& [name, plane] : result.aovs) planes[py::str(name)] = arrayOf(plane);
  return py::make_tuple(image, planes);
}

py::dict bench(const py::object& scene, std::optional<uint32_t> width, std::optional<uint32_t> height,
               std::optional<uint32_t> spp, const std::string& backend, uint32_t seed, std::optional<uint32_t> maxDepth,
               uint32_t warmup, uint32_t threads) {
  const api::RenderOptions options = optionsOf(width, height, spp, backend, seed, maxDepth, {}, {}, {}, threads);
  const api::Scene loaded = sceneOf(scene);
  api::BenchResult r;
  {
    py::gil_scoped_release release;
    r = api::bench(loaded, options, warmup);
  }
  // The keys of `candela bench`'s JSON.
  py::dict d;
  d["scene"] = r.scene;
  d["width"] = r.width;
  d["height"] = r.height;
  d["spp"] = r.samplesPerPixel;
  d["max_depth"] = r.maxDepth;
  d["backend"] = r.backend;
  d["device"] = r.device;
  d["seconds"] = r.seconds;
  d["msamples_per_s"] = r.msamplesPerSecond;
  d["mrays_per_s"] = r.mraysPerSecond;
  d["invalid_samples"] = r.invalidSamples;
  d["warmup_frames"] = warmup;
  d["median_ms_per_frame"] = r.medianMsPerFrame;
  d["backend_start_seconds"] = r.backendStartSeconds;
  d["first_frame_seconds"] = r.firstFrameSeconds;
  return d;
}

api::Scene load(const py::object& path, const std::optional<std::string>& env, const std::optional<std::string>& camera,
                bool cache, bool allowOutsidePaths) {
  if (!py::isinstance<py::str>(path) && !py::hasattr(path, "__fspath__"))
    throw py::type_error("load: a path or a built-in scene's name");
  const std::string spec = py::module_::import("os").attr("fspath")(path).cast<std::string>();
  api::LoadOptions options{env.value_or(""), camera.value_or(""), cache, allowOutsidePaths};
  py::gil_scoped_release release;
  return api::Scene::load(spec, options);
}

}  // namespace

PYBIND11_MODULE(candela, m) {
  m.doc() = "candela, a physically based path tracer: render scenes to linear float32 NumPy images.";
  m.attr("__version__") = api::version();
  py::register_exception<api::Error>(m, "Error", PyExc_RuntimeError);
  candela::python::bindScenes(m);

  py::class_<RenderProgress>(m, "Progress", "Where a render stands, as its callback sees it.")
      .def_readonly("samples", &RenderProgress::samples, "samples per pixel rendered so far")
      .def_readonly("spp", &RenderProgress::samplesPerPixel, "samples per pixel asked for")
      .def_readonly("seconds", &RenderProgress::seconds, "since the first sample started")
      .def("image", &RenderProgress::image, "The image of the samples so far (not denoised), H x W x 3.");

  m.def("render", &render, py::arg("scene") = "cornell-box", py::kw_only(), py::arg("width") = py::none(),
        py::arg("height") = py::none(), py::arg("spp") = py::none(), py::arg("backend") = "auto", py::arg("seed") = 0,
        py::arg("max_depth") = py::none(), py::arg("denoise") = py::none(),
        py::arg("aovs") = std::vector<std::string>{}, py::arg("callback") = py::none(), py::arg("shading") = py::none(),
        py::arg("threads") = 0,
        "Renders a scene (a path, a built-in name, a candela.Scene or a candela.LoadedScene) as `candela render` "
        "does and returns the linear image, float32 H x W x 3; with aovs (albedo, normal, depth), (image, {name: "
        "array}). Unset width, height, spp and max_depth come from the scene file, else 512, 512, 64, 8. denoise: "
        "atrous, bilateral or optix. callback(progress) runs after each sample per pixel; returning False ends the "
        "render with the samples so far. Raises candela.Error with the command's message.");
  m.def("bench", &bench, py::arg("scene") = "cornell-box", py::kw_only(), py::arg("width") = py::none(),
        py::arg("height") = py::none(), py::arg("spp") = py::none(), py::arg("backend") = "auto", py::arg("seed") = 0,
        py::arg("max_depth") = py::none(), py::arg("warmup") = 0, py::arg("threads") = 0,
        "Times a render as `candela bench` does (16 spp by default) and returns its numbers as a dict.");
  m.def("load", &load, py::arg("path"), py::kw_only(), py::arg("env") = py::none(), py::arg("camera") = py::none(),
        py::arg("cache") = false, py::arg("allow_outside_paths") = false,
        "Loads a scene file or a built-in scene once, for several renders.");
}
