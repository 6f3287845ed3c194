// gearfem command-line interface: argument parsing, parameter handling, output folder,
// run.json, and the mapping of errors to exit statuses (see base/errors.h).
#include "base/atomic_file.h"
#include "base/errors.h"
#include "base/number.h"
#include "commands/command.h"
#include "params/checked.h"
#include "gearfem/version.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <chrono>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace gearfem::commands
{
  namespace
  {
    void print_usage(std::ostream &out)
    {
      out << "gearfem " << version_string << " (" << git_hash << ")\n"
          << "Finite-element spur-gear contact analysis.\n\n"
          << "Usage: gearfem <command> <file.prm> [--output-dir DIR] [--validate] [--resume]\n"
          << "       gearfem solve <file.prm> --condensed condensed.h5 [--output-dir DIR]\n"
          << "       gearfem batch <study.prm> [--output-dir DIR] [--validate] [--slice K/N] [--merge]\n"
          << "       gearfem <command> --print-parameters [json|prm]\n"
          << "       gearfem <command> --help\n"
          << "       gearfem --version\n\nCommands:\n";
      for (const auto &c : registry())
        out << "  " << std::left << std::setw(11) << c.name << c.summary << "\n";
      out << "\nExit status: 0 success, 2 bad input, 3 solver failure, 4 batch finished with failed\n"
             "or missing jobs (status column of batch.csv), 1 internal error.\n";
    }

    void declare_output(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry("Directory", "", dealii::Patterns::Anything(),
                        "Output folder. Empty: results/<input file name without .prm>. "
                        "The command-line option --output-dir overrides it.");
      prm.leave_subsection();
    }

    std::string json_escape(const std::string &s)
    {
      std::string r;
      for (char c : s)
        {
          if (c == '"' || c == '\\')
            r += '\\';
          if (c == '\n')
            {
              r += "\\n";
              continue;
            }
          r += c;
        }
      return r;
    }

    /// input.prm (the parameter file as read) and run.json (the run record) in the output folder.
    void write_run_record(const Command &cmd, const RunContext &ctx, double wall)
    {
      if (!ctx.input_file.empty())
        {
          std::ifstream in(ctx.input_file);
          std::stringstream content;
          content << in.rdbuf();
          write_file_atomically(ctx.output_dir / "input.prm", content.str());
        }
      std::time_t now = std::time(nullptr);
      char date[64];
      std::strftime(date, sizeof(date), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
      std::ostringstream j;
      j << "{\n  \"program\": \"gearfem\",\n  \"version\": \"" << version_string
        << "\",\n  \"git_hash\": \"" << git_hash << "\",\n  \"command\": \"" << cmd.name
        << "\",\n  \"command_line\": \"" << json_escape(ctx.command_line)
        << "\",\n  \"input\": \"" << json_escape(ctx.input_file.string())
        << "\",\n  \"finished_utc\": \"" << date << "\",\n  \"wall_time_s\": " << wall;
      if (ctx.outcome)
        for (const auto &[name, value] : ctx.outcome->record_members)
          j << ",\n  \"" << json_escape(name) << "\": " << value;
      j << "\n}\n";
      write_file_atomically(ctx.output_dir / "run.json", j.str());
    }

    /// Command-line options that are not part of the RunContext.
    struct CliOptions
    {
      bool help = false, print_parameters = false;
      std::string print_format, output_dir;
    };

    /// Parse argv[2..] into ctx (flags, arguments) and the returned options; InputError
    /// names an unknown or malformed option.
    CliOptions parse_options(const Command &cmd, int argc, char **argv, RunContext &ctx)
    {
      CliOptions o;
      for (int i = 2; i < argc; ++i)
        {
          const std::string a = argv[i];
          if (a == "--help" || a == "-h")
            {
              std::cout << "gearfem " << cmd.name << ": " << cmd.summary << "\n\n"
                        << cmd.description << "\n\nOptions:\n"
                        << "  --output-dir DIR           output folder (default results/<case>)\n"
                        << "  --validate                 parse and check the input only\n"
                        << "  --resume                   continue an interrupted run (solve)\n"
                        << "  --condensed FILE           re-solve on a condensed cycle (solve, helical)\n"
                        << "  --slice K/N                run designs K, K+N, ... only (batch)\n"
                        << "  --merge                    aggregate finished jobs, run nothing (batch)\n"
                        << "  --print-parameters [json|prm]  all parameters with defaults\n";
              o.help = true;
              return o;
            }
          else if (a == "--validate")
            ctx.validate_only = true;
          else if (a == "--resume")
            ctx.resume = true;
          else if (a == "--merge")
            ctx.merge = true;
          else if (a == "--condensed")
            {
              if (i + 1 >= argc)
                throw InputError("--condensed", "(missing)", "a condensed.h5 file (gearfem condense)");
              ctx.condensed = argv[++i];
            }
          else if (a == "--slice")
            {
              const std::string v = i + 1 < argc ? argv[++i] : "(missing)";
              const auto slash    = v.find('/');
              if (slash == std::string::npos)
                throw InputError("--slice", v, "K/N with 1 <= K <= N");
              ctx.slices = parse_int("--slice", v.substr(slash + 1), 1, 1000000);
              ctx.slice  = parse_int("--slice", v.substr(0, slash), 1, ctx.slices);
            }
          else if (a == "--batch-worker") // internal: started by a batch rank (batch/isolation.h)
            {
              if (i + 1 >= argc)
                throw InputError("--batch-worker", "(missing)", "IN,OUT,PARENT (internal to gearfem batch)");
              ctx.batch_worker = argv[++i];
            }
          else if (a == "--print-parameters")
            {
              o.print_parameters = true;
              o.print_format     = "prm";
              if (i + 1 < argc && argv[i + 1][0] != '-')
                o.print_format = argv[++i];
              if (o.print_format != "prm" && o.print_format != "json")
                throw InputError("--print-parameters", o.print_format, "{json, prm}");
            }
          else if (a == "--output-dir")
            {
              if (i + 1 >= argc)
                throw InputError("--output-dir", "(missing)", "a folder name");
              o.output_dir = argv[++i];
            }
          else if (a.size() > 1 && a[0] == '-')
            throw InputError("command-line option", a,
                             "--output-dir, --validate, --resume, --condensed, --slice, --merge, --print-parameters, --help");
          else
            ctx.arguments.push_back(a);
        }

      return o;
    }

    /// Read and check the input file of ctx into prm (InputError naming the entry).
    void read_input(const Command &cmd, dealii::ParameterHandler &prm, RunContext &ctx)
    {
      for (const auto &a : ctx.arguments)
        if (a.size() > 4 && (a.substr(a.size() - 4) == ".prm" || a.substr(a.size() - 5) == ".json"))
          ctx.input_file = a;
      if (cmd.needs_input && ctx.input_file.empty())
        throw InputError("input file", "(none)", "a .prm file",
                         "usage: gearfem " + cmd.name + " <file.prm>");
      if (!ctx.input_file.empty() && !std::filesystem::is_regular_file(ctx.input_file))
        throw InputError("input file", ctx.input_file.string(), "an existing readable file",
                         "file not found");
      if (ctx.input_file.empty() || !cmd.parse_input)
        return;
      try
        {
          // A case file may carry the sections of other commands (demo.prm serves
          // profile, mesh and solve): check it against every command's parameters, so
          // that a misspelt entry is still an error, then read this command's part.
          dealii::ParameterHandler all;
          for (const auto &other : registry())
            if (other.declare && other.parse_input)
              other.declare(all);
          declare_output(all);
          all.parse_input(ctx.input_file.string(), "", false, false);
          prm.parse_input(ctx.input_file.string(), "", true, false);
          // parse_input() does not match a value containing '{' against its pattern,
          // and Patterns::Double accepts subnormal numbers that get_double() refuses
          // (see params/checked.h): check every entry this command reads strictly, naming
          // "Section/Entry" (the other commands' entries are theirs to check when they run).
          params::check_entries(prm);
        }
      catch (const dealii::ExceptionBase &e)
        {
          throw InputError("in " + ctx.input_file.string() + ": " + params::exception_text(e));
        }
    }

  } // namespace

  void parse_input_text(const std::string &text, const std::string &name, dealii::ParameterHandler &prm)
  {
    try
      {
        dealii::ParameterHandler all;
        for (const auto &other : registry())
          if (other.declare && other.parse_input)
            other.declare(all);
        declare_output(all);
        all.parse_input_from_string(text, "", false);
        prm.parse_input_from_string(text, "", true);
        params::check_entries(prm); // the entries this job reads (parse_input above)
      }
    catch (const dealii::ExceptionBase &e)
      {
        throw InputError("in " + name + ": " + params::exception_text(e));
      }
  }

  namespace
  {
    int run_command(const Command &cmd, int argc, char **argv)
    {
      RunContext ctx;
      RunContext::Outcome outcome;
      ctx.out     = &std::cout;
      ctx.outcome = &outcome;
      for (int i = 0; i < argc; ++i)
        ctx.command_line += (i ? " " : "") + std::string(argv[i]);
      const CliOptions opt = parse_options(cmd, argc, argv, ctx);
      if (opt.help)
        return 0;

      if (ctx.resume && cmd.name != "solve")
        throw InputError("--resume", cmd.name, "the solve command", "only `gearfem solve` keeps a journal to resume");
      if (!ctx.condensed.empty() && cmd.name != "solve" && cmd.name != "helical")
        throw InputError("--condensed", cmd.name, "the solve or helical command",
                         "only `gearfem solve` and `gearfem helical` re-solve on a condensed cycle");
      if (!ctx.condensed.empty() && ctx.resume)
        throw InputError("--resume", "with --condensed", "a full solve", "a condensed run keeps no journal");
      if ((ctx.merge || ctx.slices > 1) && cmd.name != "batch")
        throw InputError(ctx.merge ? "--merge" : "--slice", cmd.name, "the batch command");
      if (!ctx.batch_worker.empty() && (cmd.name != "batch" || ctx.merge || ctx.slices > 1 || ctx.validate_only))
        throw InputError("--batch-worker", cmd.name, "the batch command alone", "it is internal to gearfem batch");
      dealii::ParameterHandler prm;
      cmd.declare(prm);
      declare_output(prm);

      if (opt.print_parameters)
        {
          prm.print_parameters(std::cout, opt.print_format == "json" ?
                                            dealii::ParameterHandler::JSON :
                                            dealii::ParameterHandler::PRM);
          return 0;
        }

      read_input(cmd, prm, ctx);

      prm.enter_subsection("Output");
      const std::string prm_dir = prm.get("Directory");
      prm.leave_subsection();
      if (!opt.output_dir.empty())
        ctx.output_dir = opt.output_dir;
      else if (!prm_dir.empty())
        ctx.output_dir = prm_dir;
      else
        ctx.output_dir = std::filesystem::path("results") /
                         ((ctx.input_file.empty() || !cmd.parse_input) ?
                            cmd.name :
                            ctx.input_file.stem().string());

      if (ctx.validate_only)
        {
          cmd.run(prm, ctx);
          if (outcome.write_record)
            std::cout << "input is valid: " << ctx.input_file.string() << std::endl;
          return outcome.exit_status;
        }

      const bool existed = std::filesystem::exists(ctx.output_dir);
      if (!cmd.creates_output_dir)
        std::filesystem::create_directories(ctx.output_dir);
      const auto t0 = std::chrono::steady_clock::now();
      try
        {
          cmd.run(prm, ctx);
        }
      catch (...)
        {
          // Leave no empty folder behind for a run that failed before writing anything.
          std::error_code ec;
          if (!existed && std::filesystem::is_empty(ctx.output_dir, ec))
            std::filesystem::remove(ctx.output_dir, ec);
          throw;
        }
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

      if (!outcome.write_record)
        return outcome.exit_status;
      write_run_record(cmd, ctx, wall);
      std::cout << "results in " << ctx.output_dir.string() << " (" << std::fixed
                << std::setprecision(2) << wall << " s)" << std::endl;
      return outcome.exit_status;
    }
  } // namespace

  bool run_plot_script(const std::string &script_name, const std::vector<std::string> &args,
                       std::ostream *out)
  {
    std::filesystem::path script = std::filesystem::path(GEARFEM_SCRIPTS_DIR) / script_name;
    if (const char *src = std::getenv("GEARFEM_SOURCE_DIR"))
      script = std::filesystem::path(src) / "scripts" / script_name;
    const std::string python = "/usr/bin/python3";
    if (!std::filesystem::exists(python) || !std::filesystem::exists(script))
      {
        if (out)
          *out << "warning: cannot plot (" << python << " or " << script << " missing)" << std::endl;
        return false;
      }
    std::string cmd = "MPLBACKEND=Agg " + python + " '" + script.string() + "'";
    for (const auto &a : args)
      cmd += " '" + a + "'";
    cmd += " > /dev/null 2>&1";
    const int rc = std::system(cmd.c_str());
    if (rc != 0 && out)
      *out << "warning: plot script " << script_name << " failed (status " << rc << ")" << std::endl;
    return rc == 0;
  }

  int main(int argc, char **argv)
  {
    try
      {
        if (argc < 2)
          {
            print_usage(std::cerr);
            return 2;
          }
        const std::string first = argv[1];
        if (first == "--help" || first == "-h" || first == "help")
          {
            print_usage(std::cout);
            return 0;
          }
        if (first == "--version")
          {
            std::cout << "gearfem " << version_string << " (git " << git_hash << ")" << std::endl;
            return 0;
          }
        for (const auto &c : registry())
          if (c.name == first)
            return run_command(c, argc, argv);
        std::string names;
        for (const auto &c : registry())
          names += (names.empty() ? "" : ", ") + c.name;
        throw InputError("command", first, "{" + names + "}");
      }
    catch (const InputError &e)
      {
        std::cerr << "gearfem: error: " << e.what() << std::endl;
        return 2;
      }
    catch (const SolverError &e)
      {
        std::cerr << "gearfem: solver failure: " << e.what() << std::endl;
        return 3;
      }
    catch (const dealii::ExceptionBase &e)
      {
        // Last line of defence: a ParameterHandler conversion that a command still makes
        // without params::get_* ("Can't convert the parameter value <...> for entry <...>")
        // is bad input, not a bug of the computation. Every entry is read through
        // params/checked.h, so this is not expected to trigger.
        const std::string text = params::exception_text(e);
        if (text.find("the parameter value") != std::string::npos ||
            text.find("for entry <") != std::string::npos)
          {
            std::cerr << "gearfem: error: invalid parameter value: " << text << std::endl;
            return 2;
          }
        std::cerr << "gearfem: internal error: " << text << std::endl;
        return 1;
      }
    catch (const std::exception &e)
      {
        std::cerr << "gearfem: internal error: " << e.what() << std::endl;
        return 1;
      }
  }
} // namespace gearfem::commands
