#pragma once
// Fault isolation of batch jobs: each rank runs its jobs in a supervised worker process
// (`gearfem batch ... --batch-worker`, started once and kept from job to job with its
// factorised model and condensed cycle). A job that crashes the worker (a signal), makes it
// exit, or runs over `Batch/Job time limit` (the worker is killed) is recorded as failed
// with the signal or the limit; the rank starts a new worker for its next job, and the
// other jobs and the merge go on.
//
// Why a process and not a thread or a signal handler: a segmentation fault or an abort in
// one design leaves the address space undefined; only a separate process can be discarded.
// The worker is a fresh program image (posix_spawn of /proc/self/exe, no fork of the MPI
// rank) with the MPI launcher's environment removed, so it starts as a singleton MPI process
// of its own (PETSc/MUMPS on MPI_COMM_SELF) and never touches the ranks' MPI_COMM_WORLD. It
// dies with its rank (PR_SET_PDEATHSIG): a killed batch leaves no worker behind.
#include "batch/job.h"

#include <sys/types.h>

#include <filesystem>
#include <string>

namespace gearfem::batch
{
  /// Runs the jobs of one rank in a supervised worker process.
  class JobSupervisor
  {
  public:
    /// `input_file` and `output_dir` are those of the batch (the worker reads the same study).
    JobSupervisor(const Study &study, std::filesystem::path input_file, std::filesystem::path output_dir);
    ~JobSupervisor(); ///< ends the worker (closes its job pipe, waits for it)
    JobSupervisor(const JobSupervisor &) = delete;
    JobSupervisor &operator=(const JobSupervisor &) = delete;

    /// Run design `i` in the worker (started if none is alive). Never throws: a worker that
    /// dies or runs over the time limit gives a failed record naming the signal or limit.
    JobRecord run(std::size_t i);
    std::size_t workers_started() const { return started_; }

  private:
    void start();
    void stop(bool kill_it);
    const Study &study_;
    std::filesystem::path input_, output_dir_, root_;
    pid_t pid_  = -1;
    int to_     = -1; ///< job indices to the worker
    int from_   = -1; ///< "done <i>" lines from the worker
    std::string pending_; ///< bytes read from the worker after the last full line
    std::size_t started_ = 0;
  };

  /// The worker's loop (`gearfem batch study.prm --batch-worker IN,OUT,PARENT`): reads job
  /// indices from fd `in`, one per line, runs each (run_job with one ModelCache for all), and
  /// answers "done <i>" on fd `out`. Returns at the end of its input or when `parent` is gone.
  void serve_jobs(const Study &study, const std::filesystem::path &jobs_root, int in, int out, pid_t parent);

  /// "segmentation fault (signal 11, SIGSEGV)" and the like.
  std::string describe_signal(int signal);
} // namespace gearfem::batch
