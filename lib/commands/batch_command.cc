// `gearfem batch study.prm`: the `solve` chain over the designs of a study (a solve case
// file plus `subsection Batch`), over MPI ranks with dynamic assignment (lib/batch). Writes
// jobs/<design id>/ (results.h5, design.prm, job.txt) and batch.csv, batch.h5; restarts skip
// finished jobs; a failed design is recorded and the batch goes on (docs/batch.md).
#include "base/atomic_file.h"
#include "base/errors.h"
#include "batch/isolation.h"
#include "batch/run.h"
#include "batch/study.h"
#include "commands/command.h"
#include "solve/input.h"
#include "post/parameters.h"

#include <deal.II/base/multithread_info.h>
#include <deal.II/base/parameter_handler.h>

#include <cstdio>
#include <fstream>
#include <iomanip>
#include <optional>
#include <sstream>

namespace gearfem::commands
{
  namespace batch_job
  {
    void declare(dealii::ParameterHandler &prm)
    {
      solve::declare_gear_contact_input(prm);
      post::declare_post_parameters(prm);
      batch::declare_batch_parameters(prm);
    }

    /// Throws InputError listing every invalid design (--validate).
    void validate_designs(const batch::Study &study, std::ostream *out)
    {
      const auto bad = batch::check_designs(study);
      if (out)
        *out << "batch: " << study.designs.designs.size() - bad.size() << " of " << study.designs.designs.size()
             << " designs pass the checks of `solve`" << std::endl;
      if (bad.empty())
        return;
      std::ostringstream m;
      m << bad.size() << " of " << study.designs.designs.size() << " designs are invalid:";
      for (const auto &[i, msg] : bad)
        m << "\n  design " << study.designs.designs[i].id << " (" << study.designs.designs[i].origin << "): " << msg;
      throw InputError(m.str());
    }

    /// Read the study and check it (all designs with --validate). Every rank reads the same
    /// files and finds the same error: only rank 0 reports it (InputError), the others
    /// return nullopt with exit status 2.
    std::optional<batch::Study> load(dealii::ParameterHandler &prm, const RunContext &ctx,
                                     const ranks::MpiSession &mpi, std::ostream *out)
    {
      try
        {
          batch::Study study = batch::load_study(prm, ctx.input_file);
          if (out)
            {
              *out << "batch: " << study.designs.designs.size() << " designs from " << study.source_name << ", "
                   << study.designs.paths.size() << " parameter path"
                   << (study.designs.paths.size() == 1 ? "" : "s") << ":";
              for (const auto &p : study.designs.paths)
                *out << " '" << p << "'";
              *out << std::endl;
            }
          if (ctx.validate_only)
            validate_designs(study, out);
          return study;
        }
      catch (const InputError &)
        {
          mpi.barrier(); // every rank has found the error: nothing was created yet
          if (mpi.rank() != 0)
            return std::nullopt; // exit status 0: see run()

          throw;
        }
    }

    /// `--batch-worker IN,OUT,PARENT`: the supervised worker process of one rank.
    void serve(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      ctx.outcome->write_record = false; // the batch's rank 0 writes run.json
      dealii::MultithreadInfo::set_thread_limit(1);
      int in = -1, out = -1;
      long parent = -1;
      if (std::sscanf(ctx.batch_worker.c_str(), "%d,%d,%ld", &in, &out, &parent) != 3 || in < 0 || out < 0 || parent <= 0)
        throw InputError("--batch-worker", ctx.batch_worker, "IN,OUT,PARENT (internal to gearfem batch)");
      const batch::Study study = batch::load_study(prm, ctx.input_file);
      batch::serve_jobs(study, ctx.output_dir / batch::jobs_folder, in, out, pid_t(parent));
    }

    void run(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      if (!ctx.batch_worker.empty())
        {
          serve(prm, ctx);
          return;
        }
      ranks::MpiSession mpi;
      // Each rank runs the serial chain: one thread per rank (the ranks are the parallelism).
      dealii::MultithreadInfo::set_thread_limit(1);
      std::ostream *out = mpi.rank() == 0 ? ctx.out : nullptr;
      if (mpi.rank() != 0)
        ctx.outcome->write_record = false; // rank 0 writes run.json and prints
      const auto study = load(prm, ctx, mpi, out);
      if (!study || ctx.validate_only)
        return;
      if (mpi.rank() == 0)
        std::filesystem::create_directories(ctx.output_dir);
      mpi.barrier();
      if (mpi.rank() == 0 && study->batch.source == batch::BatchParameters::Source::table && !ctx.merge)
        {
          std::ifstream in(study->source_name.substr(std::string("design table ").size()));
          std::ostringstream s;
          s << in.rdbuf();
          write_file_atomically(ctx.output_dir / "design_table.csv", s.str());
        }
      batch::BatchOptions opt;
      opt.output_dir = ctx.output_dir;
      opt.out        = out;
      opt.slice = ctx.slice, opt.slices = ctx.slices;
      opt.merge_only = ctx.merge;
      opt.input_file = ctx.input_file;
      const batch::BatchOutcome r = batch::run_batch(*study, mpi, opt);
      // Only rank 0's exit status carries the result (mpirun returns it). The other ranks
      // exit with 0: mpirun aborts the whole job as soon as one rank exits non-zero, which
      // could kill rank 0 before it has printed its message and written its records.
      ctx.outcome->exit_status = mpi.rank() == 0 ? r.exit_status : 0;
      if (out)
        {
          *out << "batch: " << r.mine << " designs" << (ctx.merge ? " merged" : "") << ": " << r.skipped
               << " finished before, " << r.ran << " run now, " << r.failed << " failed (" << r.invalid
               << " invalid), " << r.not_run << " not run; " << std::fixed << std::setprecision(1) << r.seconds
               << " s" << std::endl;
          if (r.exit_status != 0)
            *out << "batch: exit status " << r.exit_status
                 << ": some designs failed or did not run (status column of batch.csv); every finished job is kept"
                 << std::endl;
        }
    }
  } // namespace batch_job

  Command batch_command()
  {
    Command c;
    c.name        = "batch";
    c.summary     = "the solve chain over the designs of a study (MPI, restartable): batch.csv, batch.h5";
    c.description = "Runs `solve` for every design of a study: a solve case file plus `subsection Batch`\n"
                    "(a design table whose header names parameter paths, a full factorial, or a\n"
                    "seeded Latin hypercube). A job is one design's sweep (torques x positions);\n"
                    "jobs are handed to the MPI ranks one at a time (rank 0 manages and works).\n"
                    "Writes jobs/<design id>/{results.h5, design.prm, job.txt} and batch.csv,\n"
                    "batch.h5 (one row per design x torque). Re-running the same study skips the\n"
                    "finished jobs; a failed design is recorded in the status column.\n"
                    "Each rank runs its jobs in a supervised worker process (Batch/Job isolation):\n"
                    "a design that crashes it or runs over Batch/Job time limit is one failed job.\n"
                    "Exit status: 0 all jobs succeeded; 2 bad input (unknown parameter path,\n"
                    "malformed table: nothing runs); 4 some jobs failed or did not run.\n"
                    "Sample runs:\n"
                    "  gearfem batch inputs/batch_demo.prm --validate\n"
                    "  gearfem batch inputs/batch_demo.prm --output-dir results/batch_demo\n"
                    "  mpirun -np 2 gearfem batch inputs/batch_demo.prm --output-dir results/batch_demo\n"
                    "  gearfem batch inputs/batch_demo.prm --slice 1/4   (job-array task 1 of 4)\n"
                    "  gearfem batch inputs/batch_demo.prm --merge       (aggregate the slices)\n";
    c.declare            = batch_job::declare;
    c.run                = batch_job::run;
    c.creates_output_dir = true;
    return c;
  }
} // namespace gearfem::commands
