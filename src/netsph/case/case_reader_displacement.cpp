// [waves] type = "displacement": the paddle follows a displacement record given in the case,
// displacement = { times = [...], values = [...] } (s, m; a flap's excursion at the still-water
// level). Its Fourier series (waves/displacement_record.hpp) is the paddle's motion, and each
// harmonic, through the paddle's transfer function, a linear wave component of the target the
// gauges are compared with. The record lives in the case file, so a checkpoint's stored case
// holds it and a restart moves the paddle exactly as the run did. Same conventions as
// case_reader.cpp; docs/case-reference.md documents the keys.
#include <cmath>

#include <fmt/format.h>

#include "netsph/case/case_reader_impl.hpp"
#include "netsph/core/error.hpp"
#include "netsph/waves/dispersion.hpp"
#include "netsph/waves/displacement_record.hpp"

namespace netsph::case_detail {
namespace {

const std::vector<std::string_view> kRecordKeys = {"times", "values"};

}  // namespace

std::vector<WaveComponent> CaseReader::read_displacement_record(const TomlTableReader& r) {
  WaveSpec& w = spec_.waves;
  const double g = -spec_.fluid.gravity.z;
  const toml::node& node =
      r.require("displacement",
                "the paddle's record, { times = [0, dt, 2 dt, ...] (s), values = [...] (m) }");
  const toml::table& table = r.nested_table(
      "displacement", node,
      "must be a table such as { times = [0, 0.01, 0.02, ...], values = [0, 0.001, ...] }");
  const std::string path = r.key_path("displacement");
  TomlTableReader m(table, path, path, kRecordKeys, source_);
  DisplacementRecord record;
  const toml::node& times = m.require("times", "instants in s from 0, equally spaced");
  record.times = m.to_number_array("times", times, NumberRule::non_negative("s"), 1);
  const toml::node& values =
      m.require("values",
                "the paddle's displacement in m at each time (a flap's at the still "
                "water level)");
  record.values = m.to_number_array("values", values, NumberRule::closed(-100, 100, "m"), 1);
  if (const std::string why = displacement_record_problem(record); !why.empty())
    r.fail_value("displacement", node, fmt::format("the record {}", why));

  const std::vector<PaddleHarmonic> harmonics = record_harmonics(record);
  // Each harmonic makes the linear wave of height S (H/S)(kh) at its frequency; the phase of
  // the wave at the paddle is the harmonic's (paddle_motion.hpp's convention), so that
  // train_paddle_motion gives these harmonics back.
  std::vector<WaveComponent> components;
  double variance = 0, tallest = 0;
  for (const PaddleHarmonic& h : harmonics) {
    const double kh = wave_number(h.omega, w.depth, g) * w.depth;
    const double amplitude = 0.5 * std::fabs(h.stroke) * paddle_height_to_stroke(w.paddle, kh);
    components.push_back({h.omega / (2 * M_PI), amplitude, h.phase});
    variance += 0.5 * amplitude * amplitude;
    if (amplitude > tallest) tallest = amplitude, w.record_period = 2 * M_PI / h.omega;
  }
  w.record_height = 4 * std::sqrt(variance);
  if (w.record_period > spec_.simulation.end_time) {
    r.fail_value("displacement", node,
                 fmt::format("makes waves whose tallest has a period of {:.4g} s, longer than the "
                             "run (simulation.end_time = {} s): not one wave would be made",
                             w.record_period, format_number(spec_.simulation.end_time)));
  }
  w.record_length = record.times[1] * static_cast<double>(record.times.size());
  return components;
}

}  // namespace netsph::case_detail
