#include "batch/run.h"

#include "batch/isolation.h"

#include "base/errors.h"
#include "base/number.h"
#include "fem/direct_solver.h"

#include <deal.II/base/parameter_handler.h>

#include <chrono>
#include <cstdio>
#include <exception>
#include <map>
#include <memory>
#include <set>
#include <mutex>
#include <thread>

namespace gearfem::batch
{
  namespace
  {
    /// Rank 0's progress lines: jobs done/total, failures, elapsed time, ETA.
    class Reporter
    {
    public:
      Reporter(std::ostream *out, const Study &s, std::filesystem::path jobs_root, std::size_t total)
        : out_(out), study_(s), root_(std::move(jobs_root)), total_(total), start_(std::chrono::steady_clock::now())
      {}
      void finished(int job, bool ok, int rank, double wall, bool shared)
      {
        std::lock_guard<std::mutex> lock(m_);
        ++done_;
        failed_ += !ok;
        if (!out_)
          return;
        const double t   = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        const double eta = t / double(done_) * double(total_ - done_);
        const std::string &id = study_.designs.designs[std::size_t(job)].id;
        char buf[256];
        std::snprintf(buf, sizeof buf, "batch: job %zu/%zu done (%s, rank %d, %.1f s%s, %s), failures %zu, elapsed %.1f s, ETA %.1f s",
                      done_, total_, id.c_str(), rank, wall, shared ? ", model re-used" : "", ok ? "ok" : "FAILED",
                      failed_, t, eta);
        *out_ << buf << std::endl;
        if (!ok)
          {
            const auto rec = read_job_record(root_ / id);
            *out_ << "  " << id << ": " << (rec ? rec->message : std::string("(no job record)")) << std::endl;
          }
      }
      std::size_t failed() const { return failed_; }

    private:
      std::mutex m_;
      std::ostream *out_;
      const Study &study_;
      std::filesystem::path root_;
      std::size_t total_, done_ = 0, failed_ = 0;
      std::chrono::steady_clock::time_point start_;
    };

    /// One rank's jobs: in a supervised worker process (Batch/Job isolation = process) or in
    /// this process, with one ModelCache either way.
    class Runner
    {
    public:
      Runner(const Study &study, const BatchOptions &o) : study_(study), root_(o.output_dir / jobs_folder)
      {
        if (study.batch.isolation)
          supervisor_ = std::make_unique<JobSupervisor>(study, o.input_file, o.output_dir);
      }
      JobRecord run(std::size_t i)
      {
        return supervisor_ ? supervisor_->run(i) : run_job(study_, i, root_, &cache_);
      }

    private:
      const Study &study_;
      std::filesystem::path root_;
      ModelCache cache_;
      std::unique_ptr<JobSupervisor> supervisor_;
    };

    /// This rank's part of the jobs `todo` (rank 0's list) through the one study driver: each
    /// job in the rank's Runner, rank 0 reporting them.
    void run_jobs(const Study &study, const ranks::MpiSession &mpi, const BatchOptions &options,
                  const std::vector<int> &todo, const std::vector<std::string> &keys, Reporter *reporter)
    {
      std::unique_ptr<Runner> runner; // built on the first job: rank 0 may only manage
      ranks::DriveOptions d;
      d.run = [&](int j) {
        if (!runner)
          runner = std::make_unique<Runner>(study, options);
        const JobRecord rec = runner->run(std::size_t(j));
        return ranks::JobDone{rec.ok(), rec.wall_time, rec.shared_model};
      };
      d.finished = [&](int j, const ranks::JobDone &done, int rank) {
        if (reporter)
          reporter->finished(j, done.ok, rank, done.seconds, done.shared);
      };
      d.keys = keys;
      // A supervised worker process makes no MPI call in this process: rank 0 can always work.
      d.local_worker = mpi.size() == 1 || mpi.thread_multiple() || study.batch.isolation;
      if (!study.batch.isolation)
        d.before_local = [] { fem::initialize_petsc(); }; // not concurrently with the manager's MPI calls
      ranks::drive(mpi, todo, d);
    }

    std::vector<std::string> units_of(const Study &study)
    {
      std::vector<std::string> units;
      const auto prm = design_handler(study, 0);
      for (const auto &p : study.designs.paths)
        units.push_back(parameter_unit(*prm, p));
      return units;
    }
  } // namespace

  BatchOutcome run_batch(const Study &study, const ranks::MpiSession &mpi, const BatchOptions &o)
  {
    const auto t0 = std::chrono::steady_clock::now();
    BatchOutcome r;
    r.designs       = study.designs.designs.size();
    if (o.merge_only)
      r.mine = r.designs;
    const auto root = o.output_dir / jobs_folder;
    std::vector<int> todo;
    std::vector<std::string> keys; // model key of each job to run
    std::ostream *out = mpi.rank() == 0 ? o.out : nullptr;
    int plan_error    = 0;
    std::string plan_message;
    if (mpi.rank() == 0 && !o.merge_only)
      try
        {
          std::filesystem::create_directories(root);
          std::map<std::size_t, std::string> invalid;
          for (const auto &[i, msg] : check_designs(study))
            invalid[i] = msg;
          for (std::size_t i = 0; i < r.designs; ++i)
            {
              if (int(i % std::size_t(o.slices)) != o.slice - 1)
                continue;
              ++r.mine;
              const auto &d = study.designs.designs[i];
              if (invalid.count(i))
                {
                  record_invalid(study, i, root, invalid[i]);
                  ++r.invalid;
                  if (out)
                    *out << "batch: invalid design " << d.id << " (" << d.origin << "), recorded: " << invalid[i] << "\n";
                }
              else if (job_finished(root, d.id, job_key(study, i)))
                ++r.skipped;
              else
                {
                  todo.push_back(int(i));
                  keys.push_back(model_key(study, i));
                }
            }
          if (out)
            *out << "batch: " << r.designs << " designs" << (o.slices > 1 ? ", slice " + std::to_string(o.slice) + "/" + std::to_string(o.slices) + " holds " + std::to_string(r.mine) : std::string())
                 << "; " << r.skipped << " finished before (skipped), " << r.invalid << " invalid, " << todo.size()
                 << " jobs (" << std::set<std::string>(keys.begin(), keys.end()).size() << " distinct models) to run on " << mpi.size() << " rank" << (mpi.size() > 1 ? "s" : "")
                 << (mpi.size() == 1 ? "" : mpi.thread_multiple() ? " (rank 0 manages and works)" : " (rank 0 only manages: the MPI library has no MPI_THREAD_MULTIPLE)")
                 << std::endl;
        }
      catch (const std::exception &e)
        {
          plan_error   = 1;
          plan_message = e.what();
        }
    if (mpi.size() > 1)
      plan_error = mpi.broadcast(plan_error);
    if (plan_error && mpi.rank() != 0)
      {
        r.exit_status = 2; // rank 0 reports the error
        return r;
      }
    if (plan_error)
      throw InputError("gearfem batch: planning the jobs failed: " + plan_message);

    // From here on every rank reaches the final broadcast, whatever fails on rank 0.
    std::exception_ptr error;
    if (!o.merge_only)
      {
        if (mpi.rank() == 0)
          try
            {
              Reporter reporter(out, study, root, todo.size());
              run_jobs(study, mpi, o, todo, keys, &reporter);
              r.ran = todo.size();
            }
          catch (...)
            {
              error = std::current_exception();
            }
        else
          run_jobs(study, mpi, o, {}, {}, nullptr);
      }

    int status = 0;
    if (mpi.rank() == 0 && !error)
      try
      {
        auto outcomes = collect_outcomes(study, root);
        for (std::size_t i = 0; i < outcomes.size(); ++i)
          if (outcomes[i].torques.empty()) // not run: its rows still name its torques
            try
              {
                auto prm = design_handler(study, i);
                prm->enter_subsection("Solve");
                outcomes[i].torques = parse_double_list("Solve/Torques", prm->get("Torques"));
                prm->leave_subsection();
              }
            catch (const std::exception &)
              {}
        r.failed            = 0; // counted from the records: also the invalid and earlier ones
        for (std::size_t i = 0; i < outcomes.size(); ++i)
          {
            if (!o.merge_only && int(i % std::size_t(o.slices)) != o.slice - 1)
              continue;
            if (!outcomes[i].record)
              ++r.not_run;
            else if (!outcomes[i].record->ok())
              ++r.failed;
          }
        if (o.slices == 1 || o.merge_only)
          {
            const std::size_t rows = write_aggregate(study, units_of(study), outcomes, o.output_dir);
            if (out)
              *out << "batch: " << rows << " rows (design x torque) in " << (o.output_dir / "batch.csv").string()
                   << " and batch.h5" << std::endl;
          }
        status = r.failed + r.not_run > 0 ? exit_some_failed : 0;
      }
      catch (...)
        {
          error = std::current_exception();
        }
    if (error)
      status = 1;
    r.exit_status = mpi.size() > 1 ? mpi.broadcast(status) : status;
    if (error)
      std::rethrow_exception(error);
    r.seconds     = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
  }
} // namespace gearfem::batch
