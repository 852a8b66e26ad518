#pragma once
// A measured elevation record's waves by zero up-crossing (IAHR/PIANC 1986 wave analysis
// conventions): a wave runs from one up-crossing of the mean level to the next; its height is
// its highest crest minus its lowest trough (the extreme samples: a record sampled at dt
// underestimates a crest of a wave of frequency omega by up to a fraction (omega dt)^2 / 8),
// its period the time between the crossings (located by linear interpolation between
// samples). What a gauge's summary reports.
#include <cstddef>
#include <span>
#include <vector>

namespace netsph {

struct RecordWave {
  double start = 0;   ///< s, the up-crossing that starts it
  double period = 0;  ///< s
  double crest = 0;   ///< m above the mean level
  double trough = 0;  ///< m below the mean level (positive)
  double height() const { return crest + trough; }
};

struct WaveRecordSummary {
  double mean_level = 0;  ///< m, the record's mean elevation (the crossings' level)
  std::vector<RecordWave> waves;
  double mean_height = 0, mean_period = 0, mean_crest = 0, mean_trough = 0;  ///< over waves
  double h_third = 0;  ///< H1/3: mean height of the highest third of the waves, m
};

/// The zero up-crossing waves of elevation `eta` sampled at increasing `times` (equal
/// sizes), from `t_from` on. With fewer than two up-crossings there are no waves (all zero).
WaveRecordSummary zero_upcrossing_waves(std::span<const double> times, std::span<const double> eta,
                                        double t_from = 0);

}  // namespace netsph
