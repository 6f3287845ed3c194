#include "batch/aggregate.h"

#include "base/atomic_file.h"
#include "base/errors.h"
#include "base/number.h"

#include <algorithm>
#include <cstdio>
#include <map>

namespace gearfem::batch
{
  namespace
  {
    std::string number(double x)
    {
      require_finite_output(x, "batch.csv", "a number");
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.10g", x);
      return buf;
    }

    std::string csv_cell(const std::string &s)
    {
      if (s.find_first_of(",\"\n") == std::string::npos)
        return s;
      std::string q = "\"";
      for (const char c : s)
        q += c == '"' ? std::string("\"\"") : std::string(1, c);
      return q + "\"";
    }

    std::string label(const std::string &name, const std::string &unit)
    {
      return name + " [" + (unit.empty() ? "input" : unit) + "]";
    }

    /// The columns after the design parameters, with their unit.
    const std::vector<std::pair<std::string, std::string>> &result_columns()
    {
      static const std::vector<std::pair<std::string, std::string>> c = {
        {"torque", "N m"},
        {"positions", "-"},
        {"STE mean", "um"},
        {"STE peak-to-peak", "um"},
        {"k_secant per width mean", "N/(mm um)"},
        {"k_secant per width min", "N/(mm um)"},
        {"k_secant per width max", "N/(mm um)"},
        {"p_max", "MPa"},
        {"root stress pinion", "MPa"},
        {"root stress gear", "MPa"},
        {"contact ratio", "-"},
        {"wall time", "s"}};
      return c;
    }

    std::vector<double> result_values(const TorqueSummary &s, const JobRecord &r)
    {
      return {s.torque, double(s.positions), s.ste_mean, s.ste_peak_to_peak, s.k_mean, s.k_min, s.k_max,
              s.p_max,  s.root_pinion,       s.root_gear, r.contact_ratio,   r.wall_time};
    }

    bool numeric(const std::vector<Design> &designs, std::size_t k)
    {
      for (const auto &d : designs)
        try
          {
            (void)parse_double("", d.values[k]);
          }
        catch (const InputError &)
          {
            return false;
          }
      return true;
    }
  } // namespace

  std::vector<TorqueSummary> summarise(const io::SolveResults &results)
  {
    const auto &sw = results.sweep;
    const auto T = sw.column("torque"), ste = sw.column("STE"), k = sw.column("k_secant per width"),
               p = sw.column("p_max"), s1 = sw.column("root stress pinion"), s2 = sw.column("root stress gear");
    std::vector<TorqueSummary> out;
    std::map<double, std::size_t> where;
    for (std::size_t i = 0; i < T.size(); ++i)
      {
        auto it = where.find(T[i]);
        if (it == where.end())
          {
            it = where.emplace(T[i], out.size()).first;
            TorqueSummary s;
            s.torque = T[i];
            s.ste_mean = 0, s.k_mean = 0;
            s.k_min = s.k_max = k[i];
            s.ste_peak_to_peak = ste[i]; // min so far, turned into max - min below
            s.p_max = p[i], s.root_pinion = s1[i], s.root_gear = s2[i];
            out.push_back(s);
          }
        TorqueSummary &s = out[it->second];
        ++s.positions;
        s.ste_mean += ste[i], s.k_mean += k[i];
        s.k_min = std::min(s.k_min, k[i]), s.k_max = std::max(s.k_max, k[i]);
        s.p_max = std::max(s.p_max, p[i]);
        s.root_pinion = std::max(s.root_pinion, s1[i]), s.root_gear = std::max(s.root_gear, s2[i]);
      }
    for (auto &s : out)
      {
        double lo = 1e300, hi = -1e300;
        for (std::size_t i = 0; i < T.size(); ++i)
          if (T[i] == s.torque)
            lo = std::min(lo, ste[i]), hi = std::max(hi, ste[i]);
        s.ste_peak_to_peak = hi - lo;
        s.ste_mean /= double(s.positions), s.k_mean /= double(s.positions);
      }
    return out;
  }

  std::vector<DesignOutcome> collect_outcomes(const Study &study, const std::filesystem::path &jobs_root)
  {
    std::vector<DesignOutcome> out(study.designs.designs.size());
    for (std::size_t i = 0; i < out.size(); ++i)
      {
        const auto dir = jobs_root / study.designs.designs[i].id;
        DesignOutcome &o = out[i];
        o.record         = read_job_record(dir);
        if (o.record)
          o.torques = o.record->torques;
        if (!o.record)
          {
            o.status = "not run";
            continue;
          }
        if (!o.record->ok())
          {
            o.status = "failed: " + o.record->message;
            continue;
          }
        try
          {
            o.summaries = summarise(io::read_solve_results(dir / "results.h5", true));
            o.status    = "ok";
          }
        catch (const std::exception &e)
          {
            o.status = std::string("failed: the finished job's results cannot be read: ") + e.what();
            o.summaries.clear();
          }
      }
    return out;
  }

  std::size_t write_aggregate(const Study &study, const std::vector<std::string> &units,
                              const std::vector<DesignOutcome> &outcomes, const std::filesystem::path &dir)
  {
    const auto &designs = study.designs.designs;
    const auto &paths   = study.designs.paths;
    // CSV: every design value as written; empty result cells for a design without results.
    std::string csv = "design [-],id [text]";
    for (std::size_t k = 0; k < paths.size(); ++k)
      csv += "," + csv_cell(label(paths[k], units[k]));
    for (const auto &[n, u] : result_columns())
      csv += "," + label(n, u);
    csv += ",status [text]\n";

    // HDF5: numeric design columns and results in /batch, text in /batch too.
    Table t;
    t.add_column("design", "-");
    t.add_column("ok", "-");
    std::vector<std::size_t> numeric_paths;
    for (std::size_t k = 0; k < paths.size(); ++k)
      if (numeric(designs, k))
        {
          numeric_paths.push_back(k);
          std::string name = paths[k];
          std::replace(name.begin(), name.end(), '/', '|');
          t.add_column(name, units[k].empty() ? "input" : units[k]);
        }
    for (const auto &[n, u] : result_columns())
      t.add_column(n, u);
    std::vector<std::string> ids, statuses;
    std::map<std::size_t, std::vector<std::string>> text_values;

    std::size_t rows = 0;
    for (std::size_t i = 0; i < designs.size(); ++i)
      {
        const DesignOutcome &o = outcomes[i];
        std::vector<TorqueSummary> lines = o.summaries;
        const bool have                  = !lines.empty();
        if (!have)
          {
            if (!o.torques.empty())
              for (const double T : o.torques)
                lines.push_back(TorqueSummary{T});
            else
              lines.push_back(TorqueSummary{});
          }
        const JobRecord rec = o.record ? *o.record : JobRecord();
        for (const auto &s : lines)
          {
            std::string row = number(double(i + 1)) + "," + csv_cell(designs[i].id);
            for (const auto &v : designs[i].values)
              row += "," + csv_cell(v);
            const auto values = result_values(s, rec);
            for (std::size_t c = 0; c < values.size(); ++c)
              row += "," + (have || (c == 0 && s.torque > 0) ? number(values[c]) : std::string());
            csv += row + "," + csv_cell(o.status) + "\n";

            std::vector<double> h = {double(i + 1), have ? 1.0 : 0.0};
            for (const std::size_t k : numeric_paths)
              h.push_back(parse_double(paths[k], designs[i].values[k]));
            for (std::size_t c = 0; c < values.size(); ++c)
              h.push_back(have || c == 0 ? values[c] : 0.0);
            t.add_row(h);
            ids.push_back(designs[i].id);
            statuses.push_back(o.status);
            for (std::size_t k = 0; k < paths.size(); ++k)
              if (std::find(numeric_paths.begin(), numeric_paths.end(), k) == numeric_paths.end())
                text_values[k].push_back(designs[i].values[k]);
            ++rows;
          }
      }
    write_file_atomically(dir / "batch.csv", csv);
    std::vector<std::tuple<std::string, std::string, std::vector<std::string>>> text = {
      {"batch", "id [text]", ids}, {"batch", "status [text]", statuses}};
    for (const auto &[k, v] : text_values)
      {
        std::string name = paths[k];
        std::replace(name.begin(), name.end(), '/', '|');
        text.emplace_back("batch", name + " [text]", v);
      }
    io::write_table_file({{"batch", &t}}, dir / "batch.h5",
                         {{"format", batch_format},
                          {"format_version", batch_format_version},
                          {"study", study.file.filename().string()},
                          {"designs", study.source_name}},
                         text);
    return rows;
  }
} // namespace gearfem::batch
