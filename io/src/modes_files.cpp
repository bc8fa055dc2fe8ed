#include "unfurl/io/modes_files.hpp"

#include "unfurl/io/json_writer.hpp"
#include "unfurl/io/output_file.hpp"
#include "unfurl/sim/number_text.hpp"

namespace unfurl::io {

namespace {

// A shape entry's unit: its coordinate's, without the rate.
std::string shape_unit(const sim::Model& model, int c) {
  const std::string rate = model.velocity_unit(c);
  return rate.substr(0, rate.find("/s"));
}

}  // namespace

void write_modes_csv(const sim::Scene& scene, const sim::ModesResult& modes, const std::string& path) {
  const sim::Model& model = scene.model;
  OutputFile file(path);
  std::ostream& out = file.stream();
  out << "mode,kind,frequency_hz [Hz],damping_ratio,damped_frequency_hz [Hz]";
  for (int c = 0; c < model.nv; ++c) out << ",shape." << model.velocity_name(c) << " [" << shape_unit(model, c) << "]";
  out << '\n';
  for (std::size_t k = 0; k < modes.modes.size(); ++k) {
    const sim::Mode& m = modes.modes[k];
    out << k + 1 << ',' << sim::mode_kind_name(m.kind) << ',' << sim::format_number(m.frequency_hz) << ','
        << sim::format_number(m.damping_ratio) << ',' << sim::format_number(m.damped_frequency_hz);
    for (int c = 0; c < model.nv; ++c) out << ',' << sim::format_number(m.shape[c]);
    out << '\n';
  }
  file.commit();
}

void write_modes_json(const sim::Scene& scene, const sim::ModesResult& modes, const std::string& state,
                      const std::string& path) {
  const sim::Model& model = scene.model;
  OutputFile file(path);
  JsonWriter json(file.stream());
  json.begin_object();
  json.value("scene", scene.name).value("scene_source", scene.source);
  json.value("state", state);
  json.begin_object("q");
  for (int c = 0; c < model.nq; ++c) json.value(model.position_name(c), modes.q[c]);
  json.end_object();
  json.begin_object("latches_engaged");
  const std::vector<const sim::Latch*> latches = scene.latches();
  for (std::size_t l = 0; l < latches.size() && l < modes.engaged.size(); ++l)
    json.value(model.joints[latches[l]->joint].name, static_cast<bool>(modes.engaged[l]));
  json.end_object();
  json.value("coordinates", modes.coordinates).value("loop_rank", modes.loop_rank);
  json.value("independent_coordinates", modes.coordinates - modes.loop_rank);
  json.value("weak_loop_directions", modes.weak_loop_directions);
  json.value("settle_iterations", modes.settle_iterations);
  json.value("equilibrium_offset", modes.equilibrium_offset);
  json.value("stiffness_asymmetry", modes.stiffness_asymmetry);
  json.value("length", modes.length);
  json.begin_array("modes");
  for (std::size_t k = 0; k < modes.modes.size(); ++k) {
    const sim::Mode& m = modes.modes[k];
    json.begin_object().value("mode", static_cast<long>(k + 1)).value("kind", sim::mode_kind_name(m.kind));
    json.value("frequency_hz", m.frequency_hz).value("damping_ratio", m.damping_ratio);
    json.value("damped_frequency_hz", m.damped_frequency_hz);
    json.begin_object("shape");
    for (int c = 0; c < model.nv; ++c) json.value(model.velocity_name(c), m.shape[c]);
    json.end_object().end_object();
  }
  json.end_array();
  json.begin_object("units");
  json.value("frequency_hz", "Hz").value("damped_frequency_hz", "Hz").value("length", "m");
  json.value("equilibrium_offset", "rad (a length over the mechanism's length)");
  json.begin_object("shape");
  for (int c = 0; c < model.nv; ++c) json.value(model.velocity_name(c), shape_unit(model, c));
  json.end_object();
  json.end_object();
  json.end_object();
  file.commit();
}

}  // namespace unfurl::io
