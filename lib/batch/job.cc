#include "batch/job.h"

#include "base/atomic_file.h"
#include "base/errors.h"
#include "base/number.h"
#include "contact/gear_contact.h"
#include "solve/input.h"
#include "io/journal.h"
#include "io/solve_results.h"
#include "post/parameters.h"
#include "solve/run.h"
#include "condensed/cycle.h"
#include "condensed/resolve.h"
#include "route/route.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <chrono>
#include <cmath>
#include <map>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace gearfem::batch
{
  namespace
  {
    std::string one_line(std::string s)
    {
      for (char &c : s)
        if (c == '\n' || c == '\r')
          c = ' ';
      while (!s.empty() && s.back() == ' ')
        s.pop_back();
      return s;
    }

    std::string exact(double x)
    {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%a", x); // hexadecimal: exact round trip
      return buf;
    }

    /// A journal left by a killed run of this job is resumed only if it has the job's key.
    bool journal_matches(const std::filesystem::path &dir, const std::string &key)
    {
      const auto file = dir / solve::journal_file;
      if (!std::filesystem::exists(file))
        return false;
      try
        {
          io::JournalHeader h;
          (void)io::replay_journal(file, h);
          if (h.key == key)
            return true;
        }
      catch (const InputError &)
        {}
      std::error_code ec;
      std::filesystem::remove(file, ec);
      return false;
    }

    std::vector<double> design_torques(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Solve");
      const std::string t = prm.get("Torques");
      prm.leave_subsection();
      try
        {
          return parse_double_list("Solve/Torques", t);
        }
      catch (const InputError &)
        {
          return {};
        }
    }
  } // namespace

  void write_job_record(const std::filesystem::path &dir, const JobRecord &r)
  {
    std::ostringstream s;
    s << "gearfem-batch-job 1\nid " << r.id << "\nkey " << r.key << "\nstatus " << r.status << "\nmessage "
      << one_line(r.message) << "\nwall_time " << exact(r.wall_time) << "\ncontact_ratio " << exact(r.contact_ratio)
      << "\nshared_model " << (r.shared_model ? 1 : 0) << "\nroute " << r.route << "\ntorques";
    for (const double t : r.torques)
      s << " " << exact(t);
    s << "\nend\n";
    write_file_atomically(dir / job_record_file, s.str());
  }

  std::optional<JobRecord> read_job_record(const std::filesystem::path &dir)
  {
    std::ifstream in(dir / job_record_file);
    if (!in)
      return std::nullopt;
    std::string line;
    if (!std::getline(in, line) || line != "gearfem-batch-job 1")
      return std::nullopt;
    JobRecord r;
    bool end = false;
    while (std::getline(in, line))
      {
        const auto sp    = line.find(' ');
        const auto name  = line.substr(0, sp);
        const auto value = sp == std::string::npos ? std::string() : line.substr(sp + 1);
        if (name == "id")
          r.id = value;
        else if (name == "key")
          r.key = value;
        else if (name == "status")
          r.status = value;
        else if (name == "message")
          r.message = value;
        else if (name == "wall_time")
          r.wall_time = std::strtod(value.c_str(), nullptr);
        else if (name == "contact_ratio")
          r.contact_ratio = std::strtod(value.c_str(), nullptr);
        else if (name == "shared_model")
          r.shared_model = value == "1";
        else if (name == "route")
          r.route = value;
        else if (name == "torques")
          {
            std::istringstream v(value);
            std::string tok;
            while (v >> tok)
              r.torques.push_back(std::strtod(tok.c_str(), nullptr));
          }
        else if (name == "end")
          end = true;
      }
    if (!end)
      return std::nullopt;
    return r;
  }

  std::string job_key(const Study &study, std::size_t i)
  {
    auto prm = design_handler(study, i);
    return io::content_hash(design_parameters(*prm));
  }

  std::string model_key(const Study &study, std::size_t i)
  {
    auto prm = design_handler(study, i);
    return solve::model_key(solve::parse_gear_contact_input(*prm));
  }

  struct ModelCache::Impl
  {
    std::string key;
    /// The input the model was built from (its meshed pair) and the one it now serves.
    std::unique_ptr<solve::GearContactInput> base, current;
    std::unique_ptr<contact::GearContactModel> model;
    std::size_t builds = 0, reuses = 0;
    /// The condensed cycle of the cached model (Batch/Condensed cycle), and the torques of
    /// every design of the study by model key (scanned once).
    std::unique_ptr<condensed::CondensedCycle> cycle;
    std::map<std::string, std::vector<double>> key_torques;
    bool scanned = false;
  };

  ModelCache::ModelCache()
    : impl_(std::make_unique<Impl>())
  {}
  ModelCache::~ModelCache() = default;
  std::size_t ModelCache::builds() const { return impl_->builds; }
  std::size_t ModelCache::reuses() const { return impl_->reuses; }
  const std::string &ModelCache::key() const { return impl_->key; }

  namespace
  {
    /// The model of a job: the cached one re-targeted when the model keys match, else a
    /// new one (then cached). Without a cache, a new one owned by `own`.
    contact::GearContactModel &job_model(ModelCache *cache, const std::string &key,
                                         std::unique_ptr<solve::GearContactInput> &in,
                                         std::unique_ptr<contact::GearContactModel> &own, bool &shared)
    {
      // Without a cache the caller keeps `in`; with one, the cache takes it (the model
      // points into it).
      shared = false;
      if (!cache)
        {
          own = in->model();
          return *own;
        }
      auto &c = cache->impl();
      if (c.model && c.key == key)
        {
          if (c.base->contact.micro_geometry_as_gap)
            c.model->set_micro_geometry(*in->pair);
          c.current = std::move(in);
          ++c.reuses;
          shared = true;
          return *c.model;
        }
      c.model.reset(); // free the old factorisation before the new one is built
      c.cycle.reset();
      c.key.clear();
      c.current.reset();
      c.base  = std::move(in);
      c.model = c.base->model();
      c.key   = key;
      ++c.builds;
      return *c.model;
    }
  } // namespace

  bool job_finished(const std::filesystem::path &jobs_root, const std::string &id, const std::string &key)
  {
    const auto dir = jobs_root / id;
    const auto rec = read_job_record(dir);
    if (!rec || !rec->ok() || rec->key != key || rec->id != id)
      return false;
    try
      {
        (void)io::read_solve_results(dir / "results.h5", true);
        return true;
      }
    catch (const InputError &)
      {
        return false;
      }
  }

  JobRecord record_invalid(const Study &study, std::size_t i, const std::filesystem::path &jobs_root,
                           const std::string &message)
  {
    return record_failure(study, i, jobs_root, "invalid design: " + message);
  }

  JobRecord record_failure(const Study &study, std::size_t i, const std::filesystem::path &jobs_root,
                           const std::string &message, double wall_time)
  {
    const auto dir = jobs_root / study.designs.designs[i].id;
    std::filesystem::create_directories(dir);
    JobRecord rec;
    rec.id        = study.designs.designs[i].id;
    rec.status    = "failed";
    rec.message   = one_line(message);
    rec.wall_time = wall_time;
    try
      {
        auto prm        = design_handler(study, i);
        const auto text = design_parameters(*prm);
        rec.key         = io::content_hash(text);
        rec.torques     = design_torques(*prm);
        write_file_atomically(dir / job_parameters_file, text);
      }
    catch (const std::exception &)
      {}
    write_job_record(dir, rec);
    return rec;
  }

  namespace
  {
    /// The job on the rank's condensed cycle when Batch/Condensed cycle = auto and the
    /// designs of its model key ask for at least 3 torque sweeps (the cycle is built once, at
    /// the geometric mean of their torques, for their torque range). Returns false (and runs
    /// nothing, or leaves a note in `note`) when the full solve should run instead.
    bool run_condensed_job(const Study &study, ModelCache *cache, const std::string &key,
                           std::unique_ptr<solve::GearContactInput> &input, const solve::SolveRunOptions &opt,
                           JobRecord &rec, std::string &note)
    {
      const solve::GearContactInput &in = *input;
      if (!cache || !study.batch.condensed || opt.resume)
        return false;
      try
        {
          condensed::check_condensable(in);
        }
      catch (const InputError &)
        {
          return false;
        }
      auto &c = cache->impl();
      if (!c.scanned)
        {
          for (std::size_t j = 0; j < study.designs.designs.size(); ++j)
            try
              {
                auto prm                      = design_handler(study, j);
                const route::Request request = route::parse_request(*prm);
                if (route::choose(request).first != route::Route::full_fe)
                  continue; // a Target or Deviations design takes its own route
                auto &t = c.key_torques[solve::model_key(request.input)];
                for (const double T : design_torques(*prm))
                  t.push_back(T);
              }
            catch (const std::exception &)
              {} // an invalid design is recorded by its own job
          c.scanned = true;
        }
      const auto &Ts = c.key_torques[key];
      if (Ts.size() < 3)
        return false;
      const solve::GearContactInput *kept = input.get();
      std::unique_ptr<contact::GearContactModel> own;
      auto &model = job_model(cache, key, input, own, rec.shared_model);
      if (!c.cycle || c.cycle->key != condensed::condensed_key(*kept))
        {
          c.cycle.reset();
          c.cycle = std::make_unique<condensed::CondensedCycle>(
            condensed::cycle_for(model, *kept, condensed::cycle_range(Ts, condensed::CycleUse::given_torques)));
        }
      try
        {
          const solve::SolveRunResult r = condensed::run_condensed(*c.cycle, *kept, opt);
          if (!r.failure.empty())
            {
              note = "condensed route failed (" + r.failure + "), solved in full";
              return false;
            }
        }
      catch (const InputError &e)
        {
          note = std::string("condensed cycle not usable (") + e.what() + "), solved in full";
          return false;
        }
      rec.route  = "condensed";
      rec.status = "ok";
      return true;
    }
    /// Thrown by run_job past a design that run_routed_job solved.
    struct JobDone
    {};

    /// A design whose route is not the plain full FE (Solve/Target, Deviations): solved by
    /// route::run like `gearfem solve` would, its run-record members in record.json.
    void run_routed_job(route::Request &request, JobRecord &rec)
    {
      const route::Outcome o = route::run(request);
      rec.route              = route_token(o.route);
      std::ostringstream json;
      json << "{";
      for (std::size_t k = 0; k < o.record.size(); ++k)
        json << (k ? ",\n " : "\n ") << "\"" << o.record[k].first << "\": " << o.record[k].second;
      json << "\n}\n";
      write_file_atomically(request.output_dir / "record.json", json.str());
      if (o.failure.empty())
        rec.status = "ok", rec.message = o.why;
      else
        rec.message = "solver failure: " + o.failure;
    }
  } // namespace

  std::string route_token(route::Route r)
  {
    switch (r)
      {
        case route::Route::full_fe: return "full";
        case route::Route::condensed_cycle: return "condensed";
        case route::Route::target: return "target";
        case route::Route::hunting_cycle: return "hunting";
        case route::Route::deviations_in_geometry: return "geometry";
      }
    return "full";
  }

  JobRecord run_job(const Study &study, std::size_t i, const std::filesystem::path &jobs_root, ModelCache *cache)
  {
    const auto t0  = std::chrono::steady_clock::now();
    const auto dir = jobs_root / study.designs.designs[i].id;
    JobRecord rec;
    rec.id = study.designs.designs[i].id;
    try
      {
        std::filesystem::create_directories(dir);
        auto prm        = design_handler(study, i);
        const auto text = design_parameters(*prm);
        rec.key         = io::content_hash(text);
        rec.torques     = design_torques(*prm);
        write_file_atomically(dir / job_parameters_file, text);
        test_fault_hook(rec.id);
        std::error_code ec;
        std::filesystem::remove(dir / job_record_file, ec); // a re-run replaces the old record

        route::Request request = route::parse_request(*prm);
        rec.contact_ratio      = request.input.meshing().contact_ratio();
        request.output_dir     = dir;
        request.input_hash     = rec.key;
        request.input_name     = job_parameters_file;
        request.resume         = journal_matches(dir, rec.key);
        if (route::choose(request).first != route::Route::full_fe)
          {
            run_routed_job(request, rec);
            throw JobDone{};
          }
        auto input = std::make_unique<solve::GearContactInput>(std::move(request.input));
        const solve::GearContactInput &in = *input;
        solve::SolveRunOptions opt;
        opt.post          = request.post;
        opt.output_dir    = dir;
        opt.input_hash    = rec.key;
        opt.input_name    = job_parameters_file;
        opt.resume        = request.resume;
        const std::string key = solve::model_key(in);
        std::string note;
        if (!run_condensed_job(study, cache, key, input, opt, rec, note))
          {
            std::unique_ptr<contact::GearContactModel> own;
            // The condensed attempt may have handed the input to the cache already: its model
            // is then this design's.
            auto &model = input ? job_model(cache, key, input, own, rec.shared_model) : *cache->impl().model;
            const solve::SolveRunResult r = solve::run_solve(model, in, opt);
            if (r.failure.empty())
              rec.status = "ok", rec.message = note;
            else
              rec.message = "solver failure: " + r.failure + " (" + std::to_string(r.results.sweep.n_rows()) +
                            " positions finished, kept in results.h5)";
          }
      }
    catch (const JobDone &)
      {}
    catch (const InputError &e)
      {
        rec.message = std::string("invalid design: ") + e.what();
      }
    catch (const SolverError &e)
      {
        rec.message = std::string("solver failure: ") + e.what();
      }
    catch (const dealii::ExceptionBase &e)
      {
        std::ostringstream s;
        e.print_info(s);
        rec.message = "error: " + s.str();
      }
    catch (const std::exception &e)
      {
        rec.message = std::string("error: ") + e.what();
      }
    rec.message   = one_line(rec.message);
    rec.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    try
      {
        write_job_record(dir, rec);
      }
    catch (const std::exception &e)
      {
        rec.status  = "failed";
        rec.message = std::string("cannot write the job record: ") + e.what();
      }
    return rec;
  }
} // namespace gearfem::batch
