// Pictures of a run, headless (EGL, else OSMesa; no window): a frame at time
// t as an H x W x 3 array, and the standard plots as PNG files.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "py_types.hpp"
#include "render_options.hpp"
#include "unfurl/io/output_file.hpp"
#include "unfurl/io/png_file.hpp"
#include "unfurl/render/camera_frame.hpp"
#include "unfurl/render/frame_renderer.hpp"
#include "unfurl/render/load_arrows.hpp"
#include "unfurl/render/gl_context.hpp"
#include "unfurl/render/plot_renderer.hpp"
#include "unfurl/render/trajectory_plots.hpp"

namespace unfurl::python {

namespace py = pybind11;

void bind_pictures(py::module_& m) {
  m.def(
      "_frame",
      [](const PyRun& run, double t, int width, int height, const std::string& camera_name, double load_scale) {
        if (width < 16 || height < 16 || width > 8192 || height > 8192)
          throw py::value_error("size: 16 to 8192 pixels each way");
        const sim::Scene& scene = run.file.scene;
        const sim::Trajectory& tr = run.result.trajectory;
        if (tr.empty()) throw std::runtime_error("the run recorded no state");
        app::RenderOptions options;
        options.width = width, options.height = height, options.camera = camera_name;
        auto context = render::make_offscreen_context(options.gl);
        render::FrameRenderer renderer(scene, run.file.visuals, width, height, app::mesh_directories(scene));
        const Eigen::AlignedBox3f bounds = app::motion_bounds(options, scene, tr, renderer.view());
        const render::Camera camera = app::choose_camera(options, bounds, static_cast<float>(width) / height);
        std::vector<double> q;
        tr.coordinates_at(t, q);
        std::vector<sim::Pose> poses;
        render::poses_in_camera_frame(options.camera_frame, scene.model, q.data(), poses);
        render::Image image;
        std::vector<render::LoadArrow> arrows;
        std::string legend;
        if (load_scale > 0) {
          const render::LoadArrowScale scale =
              render::load_arrow_scale(scene, tr, bounds.diagonal().norm(), static_cast<float>(load_scale));
          arrows = render::load_arrows(scene, tr, tr.sample_at(t), poses, scale);
          legend = render::load_arrow_legend(scale);
        }
        renderer.frame(poses, render::time_caption(t), camera, image, arrows, legend);
        py::array_t<std::uint8_t> out({height, width, 3});
        auto d = out.mutable_unchecked<3>();
        for (int y = 0; y < height; ++y)
          for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) d(y, x, c) = image.pixel(x, y)[c];
        return out;
      },
      py::arg("run"), py::arg("t"), py::arg("width") = 640, py::arg("height") = 360, py::arg("camera") = "iso",
      py::arg("load_scale") = 0.0);
  m.def(
      "_plots",
      [](const PyRun& run, const std::string& dir, int width, int height) {
        io::make_directory(dir);
        auto context = render::make_offscreen_context(render::GlBackend::automatic);
        render::PlotRenderer plotter(width, height);
        render::Image image;
        std::vector<std::string> paths;
        for (const render::NamedPlot& p : render::trajectory_plots(run.file.scene, run.result.trajectory)) {
          plotter.draw(p.spec, image);
          io::write_png(image, dir + "/" + p.file, 6);
          paths.push_back(dir + "/" + p.file);
        }
        return paths;
      },
      py::arg("run"), py::arg("dir"), py::arg("width") = 1280, py::arg("height") = 720);
}

}  // namespace unfurl::python
