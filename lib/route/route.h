#pragma once
// The route of a solve: the one library call that takes a parsed `gearfem solve` input and
// decides how it is solved, then solves it and writes its results (docs/solve.md):
//   - the full FE sweep (solve::run_solve) over the positions and torques of `Solve`;
//   - a re-solve on a condensed cycle: a stored one (`--condensed FILE`) or one given in memory;
//   - `Solve/Target`: the model chosen, proved and refined on the run (model_choice), its
//     sweep in full or on a condensed cycle of the delivered model where the torques pay;
//   - a `Deviations` section: the hunting cycle on a condensed cycle (given, or built for the
//     input's torques by condensed::cycle_for), or with `Deviations/Model = geometry` the teeth
//     meshed turned by their pitch deviations and the full FE.
// `gearfem solve` parses, calls run() and writes; the batch driver calls the same function
// for each design, so that a design may carry a Target or a Deviations section. The choice and
// its reason are written to run.json (member "route").
#include "condensed/cycle.h"
#include "deviations/parameters.h"
#include "model_choice/choose.h"
#include "post/position.h"
#include "solve/input.h"
#include "solve/run.h"

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::route
{
  /// How a request is solved.
  enum class Route
  {
    full_fe,               ///< solve::run_solve on the input's model
    condensed_cycle,       ///< condensed::run_condensed on a given cycle
    target,                ///< Solve/Target: model_choice, then its delivered sweep
    hunting_cycle,         ///< Deviations on a condensed cycle (deviations::run_hunting)
    deviations_in_geometry ///< Deviations/Model = geometry: teeth turned in the mesh, full FE
  };
  std::string to_string(Route r);

  /// What to solve, parsed, and where to write it.
  struct Request
  {
    solve::GearContactInput input;
    post::PostOptions post;
    deviations::DeviationParameters dev;  ///< inactive: no Deviations section
    model_choice::FixedSettings fixed;    ///< the Mesh / FE entries the input set (Solve/Target)
    /// A stored condensed cycle (`--condensed FILE`); empty: none.
    std::filesystem::path cycle_file;
    /// A cycle given in memory (takes the place of cycle_file; not owned); null: none.
    const condensed::CondensedCycle *cycle = nullptr;
    std::filesystem::path output_dir;  ///< must exist (unless validate_only)
    std::string input_name;            ///< file name, for the results' `input` attribute
    std::string input_hash;            ///< of the input file (journal key of --resume)
    bool resume = false;               ///< continue the full FE sweep's journal
    /// Parse, check and print the route's summary, solve nothing.
    bool validate_only = false;
    std::ostream *out = nullptr;       ///< progress and summaries; null: silent
  };

  /// Declares every section a solve request reads (solve input, Post, Deviations).
  void declare_request(dealii::ParameterHandler &prm);
  /// The request of a parsed input (InputError naming the entry for a bad value); the
  /// caller sets the files, the output folder and the flags.
  Request parse_request(dealii::ParameterHandler &prm);

  /// The route `r` takes and why (InputError for a combination no route serves, naming the
  /// entry: e.g. Solve/Target with Deviations or with a given cycle).
  std::pair<Route, std::string> choose(const Request &r);

  struct Outcome
  {
    Route route = Route::full_fe;
    std::string why;                ///< the reason for the route, in words
    solve::SolveRunResult run;      ///< the tables of the final sweep (also written)
    /// The solver failure with the finished positions kept (SolverError for the caller to
    /// throw after writing), or empty.
    std::string failure;
    /// Plot scripts of scripts/ that apply to the output folder (none after validate_only).
    std::vector<std::string> plots;
    /// Extra members of run.json, (name, JSON value): cost, friction, error_estimate,
    /// model_choice, route.
    std::vector<std::pair<std::string, std::string>> record;
  };

  /// Solve `r` on the route choose() takes, write its results to r.output_dir and return
  /// them. InputError for bad input; a solver failure is returned in Outcome::failure with the
  /// finished results written.
  Outcome run(Request &r);
} // namespace gearfem::route
