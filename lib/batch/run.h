#pragma once
// The batch driver: the jobs of a study over the ranks of MPI_COMM_WORLD, with dynamic
// (manager/worker) assignment, restart, failure isolation and progress on rank 0.
//
// Scheduling is the one study driver's (ranks/ranks.h): jobs handed out one at a time to
// whichever rank asks, rank 0 a manager and a worker. Rank 0 works only with
// MPI_THREAD_MULTIPLE (its MUMPS calls MPI on MPI_COMM_SELF) or with supervised worker
// processes; else it is a pure manager (said on the console).
// One design's positions are not split across ranks: a job's set-up (mesh, factorisation,
// compliance) is a large part of its cost, and splitting would repeat it on every rank and
// break the warm start from one position to the next (docs/batch.md).
//
// A rank keeps the factorised model of its last job (ModelCache) and is handed, when one is
// left, a job of the same model key (designs that differ only in Solve/Post, or only in tip
// relief with Contact/Micro-geometry = gap), which then re-uses that model.
//
// Each job runs the serial chain on its own (MPI_COMM_SELF; PETSc's world is COMM_SELF).
// With Batch/Job isolation = process (the default) the chain runs in one supervised worker
// process per rank (batch/isolation.h): a job that crashes or runs over its time limit is a
// failed job, not the end of the batch.
#include "batch/aggregate.h"
#include "batch/study.h"
#include "ranks/ranks.h"

#include <filesystem>
#include <ostream>
#include <string>

namespace gearfem::batch
{
  /// Exit status of `gearfem batch` when the batch ran but some jobs failed or did not run
  /// (their status column says why). 0: all succeeded; 2: bad input (nothing ran).
  inline constexpr int exit_some_failed = 4;

  struct BatchOptions
  {
    std::filesystem::path output_dir;
    std::ostream *out = nullptr; ///< rank 0's console; other ranks pass nullptr
    int slice = 1, slices = 1;  ///< run only designs i with i % slices == slice - 1
    bool merge_only = false;    ///< run nothing: aggregate the job records found
    /// The study file: a worker process (Batch/Job isolation = process) reads it again.
    std::filesystem::path input_file;
  };

  struct BatchOutcome
  {
    std::size_t designs = 0;  ///< of the study
    std::size_t mine    = 0;  ///< in this slice
    std::size_t skipped = 0;  ///< finished before (restart)
    std::size_t invalid = 0;  ///< recorded without running
    std::size_t ran = 0, failed = 0, not_run = 0;
    double seconds = 0;
    int exit_status = 0; ///< 0 or exit_some_failed
  };

  /// Run the jobs of the study (collective over MPI_COMM_WORLD), then (rank 0, unless
  /// slicing) write batch.csv and batch.h5 from the job records. Every rank returns the same
  /// exit_status.
  BatchOutcome run_batch(const Study &study, const ranks::MpiSession &mpi, const BatchOptions &options);
} // namespace gearfem::batch
