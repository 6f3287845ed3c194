#pragma once
// Monte Carlo tolerance study: N seeded draws of both gears' deviations within an ISO 1328-1
// accuracy grade (deviations/parameters.h), each solved over the hunting cycle on one condensed
// cycle (deviations/hunting.h), spread over MPI ranks (sample i on rank i mod size), resumable
// from each rank's journal, then the distributions: per sample and torque the p-p STE, the
// first three mesh harmonics, the largest non-mesh order, the peak root stresses and pressure;
// their percentiles with the standard error of the mean (docs/deviations.md).
#include "condensed/cycle.h"
#include "post/position.h"
#include "solve/input.h"
#include "deviations/parameters.h"
#include "ranks/ranks.h"

#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace gearfem::deviations
{
  /// The figures of one sample at one torque [SI].
  struct SampleResult
  {
    long sample = 0;
    double torque = 0;
    double pp_ste = 0, mean_ste = 0;
    double mesh[3] = {0, 0, 0};
    double other = 0, other_order = 0;
    double root[2] = {0, 0};
    double p_max = 0;
    /// Drawn tolerancing figures (for the check that the draws match the grade): the largest
    /// |f_pt|, the span of F_p and F_r = 2 e of each gear.
    double f_pt_max[2] = {0, 0}, F_p_span[2] = {0, 0}, F_r[2] = {0, 0};
  };

  /// The figures of one sample: the hunting cycle of the draw `sample` of `dev` on `cycle`.
  std::vector<SampleResult> solve_sample(const condensed::CondensedCycle &cycle, const solve::GearContactInput &in,
                                         const DeviationParameters &dev, long sample, const post::PostOptions &post);

  /// A statistic of one figure over the samples.
  struct Statistic
  {
    std::string name, unit;
    double torque = 0;
    double mean = 0, standard_error = 0, p5 = 0, p50 = 0, p95 = 0, min = 0, max = 0;
    std::size_t n = 0;
  };
  /// Percentiles (linear interpolation between order statistics), mean and its standard error
  /// s / sqrt(n) of every figure, per torque.
  std::vector<Statistic> statistics(const std::vector<SampleResult> &samples);

  struct StudyOptions
  {
    long samples = 100;
    std::filesystem::path output_dir;
    std::ostream *out = nullptr; ///< rank 0's console; null on the others
    post::PostOptions post;
  };

  /// The study over the ranks of `mpi` (collective): the samples not yet in any rank's journal
  /// handed out one at a time by the one study driver (ranks/ranks.h), each solved on the rank
  /// that asked and appended to its journal (output_dir/samples.rank<r>.csv, one line per
  /// finished sample and torque, flushed: a killed study resumes where it stopped). Returns the
  /// number this rank solved or failed; a sample that fails (SolverError) is recorded
  /// (failed_samples) and the study goes on.
  long run_samples(const condensed::CondensedCycle &cycle, const solve::GearContactInput &in,
                   const DeviationParameters &dev, const StudyOptions &options, const ranks::MpiSession &mpi);

  /// The samples recorded as failed (failed.rank<r>.csv: sample, the solver's reason): a draw
  /// the condensed cycle cannot serve (contact beyond its stored candidates) is recorded,
  /// skipped, and not retried on resume.
  std::map<long, std::string> failed_samples(const std::filesystem::path &output_dir);

  /// Rank 0, after every rank: read all journals (complete samples of `n_torques` lines),
  /// write samples.csv (atomically) and return the samples below `samples`, sorted.
  std::vector<SampleResult> merge_samples(const std::filesystem::path &output_dir, long samples,
                                          std::size_t n_torques);
  void write_statistics(const std::vector<Statistic> &stats, const std::filesystem::path &file);
  /// Markdown table of the statistics.
  std::string statistics_table(const std::vector<Statistic> &stats);

  /// Refuses (InputError naming the entry) a tolerance study the Monte Carlo cannot run: no
  /// `Deviations/Accuracy grade`, positions that are not one pitch, an input the condensed
  /// route cannot serve, a grade outside its range of application.
  void check_study_input(const solve::GearContactInput &in, const DeviationParameters &dev);

  /// The ISO 1328-1 tolerances of both gears at `grade`, as a Markdown table.
  std::string tolerance_table(const solve::GearContactInput &in, int grade);

  /// The condensed cycle of a tolerance study: condensed::cycle_for over the input's torques
  /// for condensed::CycleUse::variants (the draws move every tooth pair's load), with its
  /// progress on `out` (may be null).
  condensed::CondensedCycle study_cycle(const solve::GearContactInput &in, std::ostream *out);

  /// The merged result of a finished (or partly finished) study in `output_dir`.
  struct StudySummary
  {
    std::vector<Statistic> statistics;
    std::size_t complete = 0;             ///< samples with every torque solved
    std::map<long, std::string> failed;   ///< failed samples and why
  };
  /// Merges the ranks' samples of the study in `output_dir` (`samples` drawn), writes
  /// statistics.csv and summary.md there, and returns them.
  StudySummary summarise_study(const std::filesystem::path &output_dir, const solve::GearContactInput &in,
                               const DeviationParameters &dev, long samples);
} // namespace gearfem::deviations
