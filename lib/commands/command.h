#pragma once
// The command interface of the gearfem CLI. Each command (profile, mesh, solve, rate,
// dynamics, bench, ...) is one Command value defined in its own file in this folder and
// listed in registry.cc. The executable only parses arguments and dispatches.
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

namespace gearfem::commands
{
  /// What a command gets besides its parameters.
  struct RunContext
  {
    std::filesystem::path input_file;   ///< the .prm file ("" for commands without input)
    std::filesystem::path output_dir;   ///< where to write (created by the CLI unless validate_only)
    std::vector<std::string> arguments; ///< positional arguments after the command name
    std::string command_line;           ///< the full command line, for run.json
    std::ostream *out = nullptr;        ///< console (rank 0 only)
    /// When true the command parses and checks its input, prints a summary and returns
    /// without writing anything.
    bool validate_only = false;
    /// `--resume`: continue an interrupted run from the journal in output_dir (solve).
    bool resume = false;
    /// `--condensed FILE` (solve): re-solve on a stored condensed cycle (gearfem condense).
    std::filesystem::path condensed;
    /// `--merge` (batch): aggregate the job records in output_dir, run nothing.
    bool merge = false;
    /// `--slice K/N` (batch): run only the designs i with i % N == K - 1.
    int slice = 1, slices = 1;
    /// `--batch-worker IN,OUT,PARENT` (batch, internal): run as the supervised worker process
    /// of a batch rank (batch/isolation.h), reading job indices from fd IN.
    std::string batch_worker;
    /// What the command reports back to the CLI (a command may change it; the CLI starts
    /// it at 0 / true).
    struct Outcome
    {
      int exit_status = 0;      ///< returned by the CLI when the command returns normally
      bool write_record = true; ///< false: no run.json/input.prm and no final line (MPI ranks > 0)
      /// Extra members of run.json: (name, JSON value), written after the standard members.
      std::vector<std::pair<std::string, std::string>> record_members;
    };
    Outcome *outcome = nullptr;
  };

  struct Command
  {
    std::string name;
    std::string summary;     ///< one line for `gearfem --help`
    std::string description; ///< several lines for `gearfem <command> --help`, with sample runs
    bool needs_input = true; ///< false for commands that run without a .prm (e.g. bench analytical)
    /// false for commands that hand the .prm to a sub-command which parses it itself (bench)
    bool parse_input = true;
    /// true: the command creates RunContext::output_dir itself (batch: rank 0 only, after
    /// its input checks, so that MPI ranks do not race to create and remove it).
    bool creates_output_dir = false;
    /// Declare every parameter the command reads (each module declares its own sections).
    std::function<void(dealii::ParameterHandler &)> declare;
    /// Run. Throws gearfem::InputError for bad input, gearfem::SolverError for failures.
    std::function<void(dealii::ParameterHandler &, const RunContext &)> run;
  };

  /// All commands, in the order `gearfem --help` lists them.
  const std::vector<Command> &registry();

  /// Checks the .prm `text` (named `name` in messages) against the parameters of every
  /// command, as the CLI checks an input file (a misspelt entry is an InputError naming it),
  /// then reads the entries `prm` declares. For callers without a file (the Python module).
  void parse_input_text(const std::string &text, const std::string &name, dealii::ParameterHandler &prm);

  /// The CLI entry point used by app/main.cc. Returns the process exit status.
  int main(int argc, char **argv);

  /// Run a Python plotting script from scripts/ with /usr/bin/python3. Returns false (and
  /// prints a warning) when python/matplotlib is unavailable or the script fails; plots
  /// are never required for the numerical results.
  bool run_plot_script(const std::string &script_name, const std::vector<std::string> &args,
                       std::ostream *out);
} // namespace gearfem::commands
