#pragma once
// The one MPI study driver: jobs handed out over the ranks of MPI_COMM_WORLD one at a time, to
// whichever rank asks (manager/worker), with the MPI session it runs in. The batch study
// (batch/run.h: one job a design, each in a supervised worker process) and the Monte Carlo
// tolerance study (deviations/study.h: one job a sample) run their jobs through it.
//
// Scheduling. Job costs differ 5-10x, so jobs are handed out one at a time. Rank 0 is the
// manager *and* a worker: a manager thread answers the other ranks' requests (MPI_Iprobe every
// few milliseconds, so it costs no core), while rank 0's main thread runs jobs like any worker.
// On a 2-core machine a pure manager would leave one of two cores idle. A job that makes MPI
// calls in this process (MUMPS on MPI_COMM_SELF) needs MPI_THREAD_MULTIPLE for that; without it
// rank 0 is a pure manager (DriveOptions::local_worker).
#include <functional>
#include <string>
#include <vector>

namespace gearfem::ranks
{
  /// MPI for the lifetime of the object (MPI_Init_thread unless already initialised; PETSc and
  /// MPI finalised in the destructor, in that order).
  class MpiSession
  {
  public:
    MpiSession();
    ~MpiSession();
    MpiSession(const MpiSession &) = delete;
    MpiSession &operator=(const MpiSession &) = delete;
    int rank() const { return rank_; }
    int size() const { return size_; }
    bool thread_multiple() const { return multiple_; }
    /// Every rank waits here.
    void barrier() const;
    /// The value of rank 0 on every rank.
    int broadcast(int value) const;

  private:
    int rank_ = 0, size_ = 1;
    bool multiple_ = false, we_initialized_ = false;
  };

  /// A finished job, as the driver reports it to rank 0.
  struct JobDone
  {
    bool ok       = true;
    double seconds = 0;  ///< its wall time [s]
    bool shared   = false; ///< it re-used state kept from an earlier job of the same key
  };

  struct DriveOptions
  {
    /// Runs job j on this rank (rank 0: in its main thread). An exception on rank 0 ends its
    /// own work, the other ranks still get their jobs, and it is rethrown at the end.
    std::function<JobDone(int job)> run;
    /// Rank 0: job j finished on `rank` (called from the manager thread or the main thread, one
    /// call at a time).
    std::function<void(int job, const JobDone &done, int rank)> finished;
    /// The key of each job of `todo` (a rank is handed a job of its last job's key while one is
    /// left, e.g. to re-use a factorised model); empty: in order.
    std::vector<std::string> keys;
    /// Rank 0 runs jobs in its main thread too (else it only manages).
    bool local_worker = true;
    /// Called on rank 0 before the manager thread starts, when it runs jobs itself (e.g. to
    /// initialise PETSc, which must not run concurrently with the manager's MPI calls).
    std::function<void()> before_local;
  };

  /// Runs the jobs of `todo` (rank 0's list; the other ranks' is ignored) over every rank:
  /// collective over MPI_COMM_WORLD, returns when every job has finished.
  void drive(const MpiSession &mpi, const std::vector<int> &todo, const DriveOptions &options);
} // namespace gearfem::ranks
