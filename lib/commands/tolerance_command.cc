// `gearfem tolerance study.prm`: the Monte Carlo tolerance study (deviations/study.h) of a `solve`
// input with `Deviations/Accuracy grade`, on MPI ranks: parse, get the condensed cycle (rank 0
// builds or reads it, the others read it), run each rank's samples, merge and report on rank 0.
#include "base/errors.h"
#include "base/memory.h"
#include "ranks/ranks.h"
#include "commands/command.h"
#include "condensed/cycle.h"
#include "condensed/resolve.h"
#include "post/parameters.h"
#include "solve/input.h"
#include "deviations/hunting.h"
#include "deviations/parameters.h"
#include "deviations/study.h"

#include <deal.II/base/multithread_info.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <iomanip>
#include <optional>
#include <sstream>

namespace gearfem::commands
{
  namespace tolerance_job
  {
    /// Thrown on ranks > 0 when rank 0 has failed and reports it: they leave without a message.
    struct LeaveQuietly
    {};

    void declare(dealii::ParameterHandler &prm)
    {
      solve::declare_gear_contact_input(prm);
      post::declare_post_parameters(prm);
      deviations::declare_deviation_parameters(prm);
      deviations::declare_tolerance_parameters(prm);
    }

    struct Inputs
    {
      solve::GearContactInput in;
      post::PostOptions post;
      deviations::DeviationParameters dev;
      deviations::ToleranceParameters tol;
    };

    Inputs parse(dealii::ParameterHandler &prm)
    {
      Inputs i{solve::parse_gear_contact_input(prm), post::parse_post_parameters(prm),
               deviations::parse_deviation_parameters(prm), deviations::parse_tolerance_parameters(prm)};
      deviations::check_study_input(i.in, i.dev);
      return i;
    }

    condensed::CondensedCycle get_cycle(const Inputs &i, const RunContext &ctx, const ranks::MpiSession &mpi,
                                        std::ostream *out)
    {
      const std::filesystem::path stored = ctx.output_dir / condensed::file_name;
      const std::filesystem::path file   = i.tol.cycle_file.empty() ? stored : std::filesystem::path(i.tol.cycle_file);
      // Rank 0 builds the cycle; the others wait for it. A failure is broadcast so that no rank
      // waits forever: rank 0 reports it, the others leave quietly.
      std::exception_ptr failure;
      if (mpi.rank() == 0 && i.tol.cycle_file.empty() && !std::filesystem::exists(stored))
        try
          {
            condensed::write_cycle(deviations::study_cycle(i.in, out), stored);
          }
        catch (...)
          {
            failure = std::current_exception();
          }
      if (mpi.broadcast(failure ? 1 : 0) != 0)
        {
          if (mpi.rank() == 0)
            std::rethrow_exception(failure);
          throw LeaveQuietly{}; // rank 0 reports the failure
        }
      condensed::CondensedCycle c = condensed::read_cycle(file);
      const condensed::Resolver check(c, i.in); // the cycle is this design's
      return c;
    }

    void run(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      ranks::MpiSession mpi;
      dealii::MultithreadInfo::set_thread_limit(1);
      std::ostream *out = mpi.rank() == 0 ? ctx.out : nullptr;
      if (mpi.rank() != 0)
        ctx.outcome->write_record = false;
      std::optional<Inputs> i;
      try
        {
          i.emplace(parse(prm));
        }
      catch (const InputError &)
        {
          mpi.barrier(); // every rank found the same error; rank 0 reports it
          if (mpi.rank() != 0)
            return;
          throw;
        }
      const int z1 = i->in.pair->gear(1).teeth(), z2 = i->in.pair->gear(2).teeth();
      const long pitches = i->dev.pitches > 0 ? i->dev.pitches : geometry::hunting_pitches(z1, z2);
      if (out)
        *out << "tolerance: " << i->tol.samples << " samples within ISO 1328-1 grade " << i->dev.grade << " ("
             << geometry::to_string(i->dev.distribution) << ", seed " << i->dev.seed << "), " << pitches
             << " pitches x " << i->in.positions().size() << " positions x " << i->in.solve.torques.size()
             << " torque(s) each\n"
             << deviations::tolerance_table(i->in, i->dev.grade);
      if (ctx.validate_only)
        return;
      if (mpi.rank() == 0)
        std::filesystem::create_directories(ctx.output_dir);
      mpi.barrier();
      std::optional<condensed::CondensedCycle> got;
      try
        {
          got.emplace(get_cycle(*i, ctx, mpi, out));
        }
      catch (const LeaveQuietly &)
        {
          return;
        }
      const condensed::CondensedCycle &cycle = *got;
      const double cpu0 = process_cpu_seconds();
      deviations::StudyOptions o;
      o.samples = i->tol.samples, o.output_dir = ctx.output_dir, o.out = out;
      o.post = i->post;
      std::string failure;
      long solved = 0;
      try
        {
          solved = deviations::run_samples(cycle, i->in, i->dev, o, mpi);
        }
      catch (const SolverError &e)
        {
          failure = e.what();
        }
      const double cpu = process_cpu_seconds() - cpu0;
      mpi.barrier();
      if (mpi.rank() != 0)
        {
          if (!failure.empty())
            std::cerr << "gearfem tolerance, rank " << mpi.rank() << ": " << failure << std::endl;
          return;
        }
      const deviations::StudySummary sum = deviations::summarise_study(ctx.output_dir, i->in, i->dev, i->tol.samples);
      const std::size_t complete         = sum.complete;
      const auto &failed                 = sum.failed;
      run_plot_script("plot_tolerance.py", {ctx.output_dir.string()}, out);
      *out << "\n" << deviations::statistics_table(sum.statistics) << "samples complete: " << complete << " of "
           << i->tol.samples << ", failed: " << failed.size() << "; rank 0 solved " << solved << " now in " << std::setprecision(3) << cpu
           << " CPU-s (" << (solved > 0 ? cpu / double(solved * pitches * long(i->in.positions().size()) *
                                                      long(i->in.solve.torques.size())) * 1e3 : 0.0)
           << " ms per solved position)\n";
      if (ctx.outcome)
        {
          std::ostringstream cost;
          cost << std::setprecision(6) << "{\"samples\": " << i->tol.samples << ", \"complete\": " << complete
               << ", \"ranks\": " << mpi.size() << ", \"rank0_solved\": " << solved << ", \"rank0_cpu_seconds\": " << cpu
               << ", \"peak_memory_mb\": " << peak_memory_mb() << "}";
          ctx.outcome->record_members.emplace_back("cost", cost.str());
        }
      for (const auto &[k, why] : failed)
        *out << "failed sample " << k << ": " << why << "\n";
      if (!failure.empty() || complete + failed.size() < std::size_t(i->tol.samples))
        throw SolverError((failure.empty() ? std::string("some samples did not finish") : failure) +
                          "\n  the finished samples are in " + ctx.output_dir.string() +
                          " (samples.rank*.csv); run the study again to resume");
      // Like a batch with failed jobs: the statistics stand on the other samples, exit 4.
      if (!failed.empty())
        ctx.outcome->exit_status = 4;
    }
  } // namespace tolerance_job

  Command tolerance_command()
  {
    Command c;
    c.name        = "tolerance";
    c.summary     = "Monte Carlo tolerance study: deviations drawn within an ISO 1328-1 grade, each over the hunting cycle";
    c.description = "Draws Tolerance/Samples pairs of gears within the ISO 1328-1:2013 tolerances of\n"
                    "Deviations/Accuracy grade (pitch, profile slope and form, runout; docs/deviations.md)\n"
                    "and solves each over the hunting cycle on one condensed cycle of the design (built\n"
                    "once, kept as condensed.h5). Samples are spread over MPI ranks; a killed study\n"
                    "resumes from the journals samples.rank<r>.csv. Writes samples.csv (per sample and\n"
                    "torque: p-p STE, mesh orders 1-3, the largest non-mesh order, peak root stresses and\n"
                    "pressure, and the drawn f_pt, F_p span and F_r), statistics.csv and summary.md\n"
                    "(mean with its standard error, 5/50/95 % percentiles) and tolerance.png.\n"
                    "Sample runs:\n"
                    "  gearfem tolerance inputs/tolerance_demo.prm\n"
                    "  mpirun -np 2 gearfem tolerance inputs/tolerance_demo.prm\n";
    c.creates_output_dir = true;
    c.declare = tolerance_job::declare;
    c.run     = tolerance_job::run;
    return c;
  }
} // namespace gearfem::commands
