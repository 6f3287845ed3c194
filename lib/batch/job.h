#pragma once
// One job of a batch: one design's sweep (torques x positions) on its own factorised
// bodies, run with the serial chain (solve::run_solve) into jobs/<design id>/:
//   design.prm    the design's parameters (the study with the design's values), as read
//   results.h5    (+ sweep.csv, pairs.csv, ...) the solve-results contract
//   job.txt       the job record, written last and atomically: its presence with
//                 `status ok` and the same key marks a finished job
//   solve.journal only while the job is unfinished (a killed batch resumes it)
// A job never throws: an invalid design, a solver failure or any other error is recorded
// with its message.
#include "batch/study.h"
#include "route/route.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gearfem::batch
{
  inline constexpr const char *job_record_file = "job.txt";
  inline constexpr const char *job_parameters_file = "design.prm";
  inline constexpr const char *jobs_folder = "jobs";

  struct JobRecord
  {
    std::string id;
    std::string key;              ///< hash of design.prm: what the results depend on
    std::string status = "failed"; ///< "ok" or "failed"
    std::string message;          ///< the error of a failed job (one line)
    double wall_time     = 0;     ///< [s]
    double contact_ratio = 0;     ///< transverse contact ratio of the design's pair [-]
    std::vector<double> torques;  ///< the design's torques [N m] (rows of the aggregate)
    /// The job re-used the factorised model of an earlier job of its rank (ModelCache): its
    /// wall time has no mesh and factorisation in it.
    bool shared_model = false;
    /// "full" (solve::run_solve) or "condensed" (condensed::run_condensed on the rank's cycle);
    /// for a design with Solve/Target or Deviations, route::run's route (route_token).
    std::string route = "full";
    bool ok() const { return status == "ok"; }
  };

  /// The job record's word for a route of route::run: full, condensed, target, hunting, geometry.
  std::string route_token(route::Route r);

  /// Write `dir`/job.txt atomically. Read it back: nullopt if missing or unreadable.
  void write_job_record(const std::filesystem::path &dir, const JobRecord &r);
  std::optional<JobRecord> read_job_record(const std::filesystem::path &dir);

  /// The restart key of design `i` (hash of its parameters). Throws like design_handler.
  std::string job_key(const Study &study, std::size_t i);

  /// True when jobs/<id> holds a finished job of this key: job.txt with status ok and the
  /// key, and a readable results.h5.
  bool job_finished(const std::filesystem::path &jobs_root, const std::string &id, const std::string &key);

  /// The model key of design `i` (solve::model_key of its parsed input; throws like
  /// design_handler): two designs with the same key share one mesh, factorisation and
  /// flexibility cache (GearContactModel::set_micro_geometry).
  std::string model_key(const Study &study, std::size_t i);

  /// One rank's factorised model, kept from job to job: a job whose model key equals the
  /// cached one re-targets the cached model to its micro-geometry (or only re-runs the
  /// sweep) instead of meshing and factorising again. The results equal those of a fresh
  /// model (tests/unit/contact/test_micro_geometry.cc, tests/regression/batch_checks.sh).
  class ModelCache
  {
  public:
    ModelCache();
    ~ModelCache();
    ModelCache(const ModelCache &) = delete;
    ModelCache &operator=(const ModelCache &) = delete;
    std::size_t builds() const; ///< models built (mesh + factorisation)
    std::size_t reuses() const; ///< jobs that re-used the cached model
    const std::string &key() const; ///< model key of the cached model ("" when empty)
    struct Impl;
    Impl &impl() { return *impl_; }

  private:
    std::unique_ptr<Impl> impl_;
  };

  /// Run design `i` into jobs_root/<id> (created). A journal of the same key left by a
  /// killed run is resumed. With a cache, a model of the same model key is re-used and the
  /// job's model is kept for the next job. Never throws; the record is also written to
  /// job.txt.
  JobRecord run_job(const Study &study, std::size_t i, const std::filesystem::path &jobs_root,
                    ModelCache *cache = nullptr);

  /// Record design `i` as failed with `message` without running it (an invalid design
  /// found by check_designs).
  JobRecord record_invalid(const Study &study, std::size_t i, const std::filesystem::path &jobs_root,
                           const std::string &message);

  /// Record design `i` as failed with `message` (its parameters and torques are written as
  /// for a job that ran): a job whose worker process died or ran over its time limit.
  JobRecord record_failure(const Study &study, std::size_t i, const std::filesystem::path &jobs_root,
                           const std::string &message, double wall_time = 0);

  /// The test-only fault hook: with GEARFEM_TEST_FAULT=<design id>:<segv|abort|hang> in the
  /// environment, the job of that design crashes, aborts or never ends, so that the fault
  /// isolation of the batch driver can be tested (tests/regression/batch_checks.sh). Does
  /// nothing for any other design or when the variable is unset.
  void test_fault_hook(const std::string &design_id);
} // namespace gearfem::batch
