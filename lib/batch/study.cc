#include "batch/study.h"

#include "route/route.h"

#include "base/errors.h"
#include "base/number.h"
#include "solve/input.h"
#include "params/checked.h"
#include "post/parameters.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace gearfem::batch
{
  namespace
  {
    /// "design table d.csv, column 'Gear 1/Tip relief amount', row 4 (design d4)"
    std::string where(const Study &s, std::size_t path, std::size_t i)
    {
      const Design &d = s.designs.designs[i];
      return s.source_name + ", column '" + s.designs.paths[path] + "', " + d.origin + " (design " + d.id + ")";
    }

    void set_by_path(dealii::ParameterHandler &prm, const Study &s, std::size_t path, std::size_t i)
    {
      const auto [sections, entry] = split_path(s.designs.paths[path]);
      const std::string &value     = s.designs.designs[i].values[path];
      if (!prm.subsection_path_exists(sections))
        throw InputError(where(s, path, i), s.designs.paths[path],
                         "the path of an entry of the case file, e.g. 'Gear 1/Tip relief amount' "
                         "(gearfem batch --print-parameters lists them)",
                         "unknown parameter path: no subsection '" + s.designs.paths[path].substr(0, s.designs.paths[path].rfind('/')) + "'");
      for (const auto &sec : sections)
        prm.enter_subsection(sec);
      try
        {
          (void)prm.get(entry);
        }
      catch (const dealii::ExceptionBase &)
        {
          for (std::size_t k = 0; k < sections.size(); ++k)
            prm.leave_subsection();
          throw InputError(where(s, path, i), s.designs.paths[path],
                           "the path of an entry of the case file (gearfem batch --print-parameters lists them)",
                           "unknown parameter path: no entry '" + entry + "'");
        }
      try
        {
          prm.set(entry, value);
        }
      catch (const dealii::ExceptionBase &e)
        {
          for (std::size_t k = 0; k < sections.size(); ++k)
            prm.leave_subsection();
          const std::string text = params::exception_text(e);
          if (text.find("not yet declared") != std::string::npos)
            throw InputError(where(s, path, i), s.designs.paths[path],
                             "the path of an entry of the case file (gearfem batch --print-parameters lists them)",
                             "unknown parameter path: no entry '" + entry + "'");
          throw InputError(where(s, path, i), value, "a value of the entry's pattern", text);
        }
      for (std::size_t k = 0; k < sections.size(); ++k)
        prm.leave_subsection();
    }

    void declare_case(dealii::ParameterHandler &prm)
    {
      route::declare_request(prm); // a design is a `gearfem solve` input, Deviations included
    }
  } // namespace

  void declare_batch_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii::Patterns;
    prm.enter_subsection("Batch");
    prm.declare_entry("Designs", "table", Selection("table|factorial|latin hypercube"),
                      "Where the designs come from: `Design table` (CSV), `Factorial` (every "
                      "combination of lists) or `Latin hypercube` (`Samples` over ranges, `Seed`). "
                      "Units: none.");
    prm.declare_entry("Design table", "", Anything(),
                      "CSV file, relative to the study file. Header: parameter paths such as "
                      "`Gear 1/Tip relief amount` or `Material/Gear 2/Young's modulus` (values in "
                      "the units of the entry), and optionally `id` (the job folder name). One row "
                      "per design. Units: none.");
    prm.declare_entry("Factorial", "", Anything(),
                      "Full factorial: `path: v1, v2, ...; path: ...`, every combination is one "
                      "design (the first path varies slowest). Units: those of each entry.");
    prm.declare_entry("Latin hypercube", "", Anything(),
                      "Latin-hypercube sampling: `path: low, high; path: ...`. Units: those of each "
                      "entry.");
    prm.declare_entry("Samples", "10", Integer(), "Number of Latin-hypercube designs. Units: none. Allowed: 1 to 1000000.");
    prm.declare_entry("Seed", "1", Integer(), "Seed of the Latin-hypercube sampling (same seed, same designs on every platform). Units: none. Allowed: >= 0.");
    prm.declare_entry("Write VTU", "false", Bool(),
                      "Write each job's VTU files as `Solve/VTU` says; false: none (they are "
                      "large). Units: none.");
    prm.declare_entry("Condensed cycle", "auto", Selection("auto|off"),
                      "auto: designs that share one FE model (the same geometry, mesh, material and contact "
                      "options; tip reliefs on the gap route, Contact/Micro-geometry = gap) and together ask for "
                      "at least 3 torque sweeps are solved on one condensed cycle per rank (gearfem condense, built "
                      "at the geometric mean of their torques for their torque range): about 0.5 ms per position "
                      "instead of 0.1-0.2 s, within 0.1 % of the full FE (docs/model-choice.md). A design the "
                      "cycle cannot serve (other positions, contact beyond the stored candidates) falls back to "
                      "the full solve; the job record says which route ran. off: a full solve per design. "
                      "Units: none.");
    prm.declare_entry("Job isolation", "process", Selection("process|none"),
                      "process: each rank runs its jobs in a supervised worker process (started once, kept from job "
                      "to job with its factorised model): a job that crashes it (a signal such as SIGSEGV), makes it "
                      "exit or runs over `Job time limit` is recorded as failed with the signal or the limit, and the "
                      "other jobs and the merge go on. none: jobs run in the rank's own process (a crash ends the "
                      "whole batch). Units: none.");
    prm.declare_entry("Job time limit", "0", Double(0),
                      "Wall time after which a job is stopped (its worker process killed) and recorded as failed; "
                      "0: no limit. Needs Job isolation = process. Units: s. Allowed: 0 (none) or 1 to 1e7.");
    prm.leave_subsection();
  }

  BatchParameters parse_batch_parameters(dealii::ParameterHandler &prm)
  {
    BatchParameters b;
    prm.enter_subsection("Batch");
    const std::string src = prm.get("Designs");
    b.source    = src == "factorial" ? BatchParameters::Source::factorial :
                  src == "latin hypercube" ? BatchParameters::Source::latin_hypercube :
                                             BatchParameters::Source::table;
    b.table     = prm.get("Design table");
    b.factorial = prm.get("Factorial");
    b.hypercube = prm.get("Latin hypercube");
    b.samples   = params::get_integer(prm, "Samples");
    const int seed = params::get_integer(prm, "Seed");
    b.write_vtu = params::get_bool(prm, "Write VTU");
    b.condensed = prm.get("Condensed cycle") == "auto";
    b.isolation = prm.get("Job isolation") == "process";
    b.job_time_limit = params::get_double(prm, "Job time limit");
    prm.leave_subsection();
    if (!std::isfinite(b.job_time_limit) || (b.job_time_limit != 0 && (b.job_time_limit < 1 || b.job_time_limit > 1e7)))
      throw InputError("Batch/Job time limit", to_string_g(b.job_time_limit) + " s", "0 (none) or 1 to 1e7 s");
    if (b.job_time_limit > 0 && !b.isolation)
      throw InputError("Batch/Job time limit", to_string_g(b.job_time_limit) + " s", "0 with Batch/Job isolation = none",
                       "a job can only be stopped in a worker process (Job isolation = process)");
    if (seed < 0)
      throw InputError("Batch/Seed", std::to_string(seed), ">= 0");
    b.seed = (unsigned long)seed;
    if (b.source == BatchParameters::Source::table && dealii::Utilities::trim(b.table).empty())
      throw InputError("Batch/Design table", "(empty)", "a CSV file name", "Batch/Designs = table needs it");
    if (b.source == BatchParameters::Source::latin_hypercube && (b.samples < 1 || b.samples > 1000000))
      throw InputError("Batch/Samples", std::to_string(b.samples), "1 to 1000000");
    return b;
  }

  Study load_study(dealii::ParameterHandler &prm, const std::filesystem::path &file)
  {
    Study s;
    s.file = file;
    std::ifstream in(file);
    std::ostringstream text;
    text << in.rdbuf();
    s.text  = text.str();
    s.batch = parse_batch_parameters(prm);
    switch (s.batch.source)
      {
        case BatchParameters::Source::table:
          {
            std::filesystem::path t = dealii::Utilities::trim(s.batch.table);
            if (t.is_relative())
              t = file.parent_path() / t;
            s.designs     = read_design_table(t.string());
            s.source_name = "design table " + t.string();
            break;
          }
        case BatchParameters::Source::factorial:
          s.designs     = full_factorial(parse_path_lists("Batch/Factorial", s.batch.factorial));
          s.source_name = "Batch/Factorial";
          break;
        case BatchParameters::Source::latin_hypercube:
          {
            std::vector<std::pair<std::string, std::pair<double, double>>> ranges;
            for (const auto &[path, v] : parse_path_lists("Batch/Latin hypercube", s.batch.hypercube, 2))
              ranges.emplace_back(path, std::make_pair(parse_double("Batch/Latin hypercube (" + path + ")", v[0]),
                                                       parse_double("Batch/Latin hypercube (" + path + ")", v[1])));
            s.designs     = latin_hypercube(ranges, std::size_t(s.batch.samples), s.batch.seed);
            s.source_name = "Batch/Latin hypercube";
            break;
          }
      }
    for (std::size_t i = 0; i < s.designs.designs.size(); ++i)
      (void)design_handler(s, i);
    return s;
  }

  std::unique_ptr<dealii::ParameterHandler> design_handler(const Study &s, std::size_t i)
  {
    auto prm = std::make_unique<dealii::ParameterHandler>();
    declare_case(*prm);
    try
      {
        prm->parse_input_from_string(s.text, "", true);
      }
    catch (const dealii::ExceptionBase &e)
      {
        throw InputError("in " + s.file.string() + ": " + params::exception_text(e));
      }
    for (std::size_t p = 0; p < s.designs.paths.size(); ++p)
      set_by_path(*prm, s, p, i);
    prm->enter_subsection("Solve");
    if (!s.batch.write_vtu)
      prm->set("VTU", "none");
    prm->set("Plots", "false");
    prm->leave_subsection();
    try
      {
        params::check_entries(*prm);
      }
    catch (const InputError &e)
      {
        const Design &d = s.designs.designs[i];
        throw InputError(s.source_name + ", " + d.origin + " (design " + d.id + "): " + e.what());
      }
    return prm;
  }

  std::string design_parameters(dealii::ParameterHandler &prm)
  {
    std::ostringstream out;
    prm.print_parameters(out, dealii::ParameterHandler::ShortPRM);
    return out.str();
  }

  std::string parameter_unit(const dealii::ParameterHandler &prm, const std::string &path)
  {
    std::stringstream s;
    prm.print_parameters(s, dealii::ParameterHandler::JSON);
    boost::property_tree::ptree tree;
    boost::property_tree::read_json(s, tree);
    const auto [sections, entry] = split_path(path);
    const boost::property_tree::ptree *node = &tree;
    for (const auto &name : sections)
      {
        auto it = node->find(name);
        if (it == node->not_found())
          it = node->find(params::mangled_name(name));
        if (it == node->not_found())
          return "";
        node = &it->second;
      }
    auto it = node->find(entry);
    if (it == node->not_found())
      it = node->find(params::mangled_name(entry));
    if (it == node->not_found())
      return "";
    const std::string doc = it->second.get<std::string>("documentation", "");
    const auto u          = doc.find("Units: ");
    if (u == std::string::npos)
      return "";
    std::string unit = doc.substr(u + 7);
    const auto dot   = unit.find('.');
    unit             = dealii::Utilities::trim(unit.substr(0, dot));
    if (unit == "none")
      return "-";
    return unit;
  }

  std::vector<std::pair<std::size_t, std::string>> check_designs(const Study &study)
  {
    std::vector<std::pair<std::size_t, std::string>> bad;
    for (std::size_t i = 0; i < study.designs.designs.size(); ++i)
      try
        {
          auto prm = design_handler(study, i);
          (void)solve::parse_gear_contact_input(*prm);
          (void)post::parse_post_parameters(*prm);
        }
      catch (const InputError &e)
        {
          bad.emplace_back(i, e.what());
        }
      catch (const SolverError &e)
        {
          bad.emplace_back(i, e.what());
        }
      catch (const dealii::ExceptionBase &e)
        {
          bad.emplace_back(i, params::exception_text(e));
        }
      catch (const std::exception &e) // a bug of a check: record it, do not stop the batch
        {
          bad.emplace_back(i, std::string("error: ") + e.what());
        }
    return bad;
  }
} // namespace gearfem::batch
