// Monte Carlo tolerance study over the hunting cycle.
#include "deviations/study.h"

#include "base/atomic_file.h"
#include "base/errors.h"
#include "base/progress.h"
#include "deviations/hunting.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

namespace gearfem::deviations
{
  namespace
  {
    constexpr int n_fields = 18;
    const char *journal_header = "sample,torque [N m],p-p STE [m],mean STE [m],mesh 1 [m],mesh 2 [m],mesh 3 [m],"
                                 "largest other [m],largest other order [-],root stress pinion [Pa],root stress "
                                 "gear [Pa],max pressure [Pa],max |f_pt| 1 [m],max |f_pt| 2 [m],F_p span 1 [m],F_p "
                                 "span 2 [m],F_r 1 [m],F_r 2 [m]";

    std::string journal_name(int rank) { return "samples.rank" + std::to_string(rank) + ".csv"; }

    std::string line(const SampleResult &r)
    {
      std::ostringstream s;
      s << std::setprecision(17) << r.sample << ',' << r.torque << ',' << r.pp_ste << ',' << r.mean_ste << ','
        << r.mesh[0] << ',' << r.mesh[1] << ',' << r.mesh[2] << ',' << r.other << ',' << r.other_order << ','
        << r.root[0] << ',' << r.root[1] << ',' << r.p_max << ',' << r.f_pt_max[0] << ',' << r.f_pt_max[1] << ','
        << r.F_p_span[0] << ',' << r.F_p_span[1] << ',' << r.F_r[0] << ',' << r.F_r[1];
      return s.str();
    }

    bool parse(const std::string &text, SampleResult &r)
    {
      std::vector<double> v;
      std::stringstream s(text);
      std::string item;
      while (std::getline(s, item, ','))
        {
          char *end = nullptr;
          const double x = std::strtod(item.c_str(), &end);
          if (end == item.c_str() || !std::isfinite(x))
            return false;
          v.push_back(x);
        }
      if (v.size() != n_fields)
        return false;
      r.sample = long(v[0]), r.torque = v[1], r.pp_ste = v[2], r.mean_ste = v[3];
      r.mesh[0] = v[4], r.mesh[1] = v[5], r.mesh[2] = v[6], r.other = v[7], r.other_order = v[8];
      r.root[0] = v[9], r.root[1] = v[10], r.p_max = v[11];
      r.f_pt_max[0] = v[12], r.f_pt_max[1] = v[13], r.F_p_span[0] = v[14], r.F_p_span[1] = v[15];
      r.F_r[0] = v[16], r.F_r[1] = v[17];
      return true;
    }

    /// Every complete sample (all `n_torques` lines) of every journal in `dir`.
    std::map<long, std::vector<SampleResult>> read_journals(const std::filesystem::path &dir, std::size_t n_torques)
    {
      std::map<long, std::vector<SampleResult>> all;
      if (!std::filesystem::exists(dir))
        return all;
      for (const auto &e : std::filesystem::directory_iterator(dir))
        {
          const std::string name = e.path().filename().string();
          if (name.rfind("samples.rank", 0) != 0 || e.path().extension() != ".csv")
            continue;
          std::ifstream in(e.path());
          std::string text;
          std::getline(in, text); // header
          std::map<long, std::vector<SampleResult>> mine;
          while (std::getline(in, text))
            {
              SampleResult r;
              if (parse(text, r))
                mine[r.sample].push_back(r);
            }
          for (auto &[k, v] : mine)
            if (v.size() == n_torques && !all.count(k))
              all[k] = v;
        }
      return all;
    }

    double percentile(const std::vector<double> &sorted, double p)
    {
      if (sorted.empty())
        return 0;
      const double x = p * double(sorted.size() - 1);
      const std::size_t i = std::size_t(std::floor(x));
      const double f = x - double(i);
      return i + 1 < sorted.size() ? sorted[i] * (1 - f) + sorted[i + 1] * f : sorted.back();
    }
  } // namespace

  std::map<long, std::string> failed_samples(const std::filesystem::path &dir)
  {
    std::map<long, std::string> failed;
    if (!std::filesystem::exists(dir))
      return failed;
    for (const auto &e : std::filesystem::directory_iterator(dir))
      {
        const std::string name = e.path().filename().string();
        if (name.rfind("failed.rank", 0) != 0 || e.path().extension() != ".csv")
          continue;
        std::ifstream in(e.path());
        std::string text;
        while (std::getline(in, text))
          {
            const auto comma = text.find(',');
            char *end        = nullptr;
            const long i     = std::strtol(text.c_str(), &end, 10);
            if (comma != std::string::npos && end == text.c_str() + comma)
              failed[i] = text.substr(comma + 1);
          }
      }
    return failed;
  }

  std::vector<SampleResult> solve_sample(const condensed::CondensedCycle &cycle, const solve::GearContactInput &in,
                                         const DeviationParameters &dev, long sample, const post::PostOptions &post)
  {
    const geometry::PairDeviations d = resolve_deviations(dev, *in.pair, std::uint64_t(sample));
    HuntingOptions opt;
    opt.pitches = dev.pitches;
    opt.post    = post;
    opt.tables  = false;
    const HuntingRun h = run_hunting(cycle, in, d, opt);
    if (!h.run.failure.empty())
      throw SolverError("sample " + std::to_string(sample) + ": " + h.run.failure);
    std::vector<SampleResult> out;
    for (std::size_t ti = 0; ti < h.summary.size(); ++ti)
      {
        SampleResult r;
        r.sample = sample, r.torque = in.solve.torques[ti];
        const auto &ste = h.ste[ti];
        const auto [lo, hi] = std::minmax_element(ste.begin(), ste.end());
        r.pp_ste = *hi - *lo;
        double sum = 0;
        for (const double v : ste)
          sum += v;
        r.mean_ste = sum / double(ste.size());
        for (int h3 = 0; h3 < 3; ++h3)
          r.mesh[h3] = h.summary[ti].mesh[h3];
        r.other = h.summary[ti].largest_other, r.other_order = h.summary[ti].largest_other_order;
        r.root[0] = h.max_root_stress[0][ti], r.root[1] = h.max_root_stress[1][ti];
        r.p_max = h.max_pressure[ti];
        for (int b = 0; b < 2; ++b)
          {
            const auto &g = d.gear[b];
            for (const double f : g.f_pt)
              r.f_pt_max[b] = std::max(r.f_pt_max[b], std::abs(f));
            const auto F = g.cumulative_pitch();
            if (!F.empty())
              r.F_p_span[b] = *std::max_element(F.begin(), F.end()) - *std::min_element(F.begin(), F.end());
            r.F_r[b] = 2 * g.eccentricity;
          }
        out.push_back(r);
      }
    return out;
  }

  long run_samples(const condensed::CondensedCycle &cycle, const solve::GearContactInput &in,
                   const DeviationParameters &dev, const StudyOptions &o, const ranks::MpiSession &mpi)
  {
    const auto done   = read_journals(o.output_dir, in.solve.torques.size());
    const auto failed = failed_samples(o.output_dir); // not retried: the same draw fails again
    std::vector<int> todo;
    for (long i = 0; i < o.samples; ++i)
      if (!done.count(i) && !failed.count(i))
        todo.push_back(int(i));
    if (o.out)
      *o.out << "tolerance: " << o.samples << " samples on " << mpi.size() << " rank" << (mpi.size() == 1 ? "" : "s")
             << ", " << done.size() << " finished and " << failed.size() << " failed before; " << todo.size()
             << " to solve" << std::endl;
    const std::filesystem::path journal = o.output_dir / journal_name(mpi.rank());
    const bool fresh = !std::filesystem::exists(journal);
    std::ofstream j(journal, std::ios::app);
    if (!j)
      throw InputError("output folder", o.output_dir.string(), "a writable folder (the sample journal)");
    if (fresh)
      j << journal_header << '\n' << std::flush;
    Progress progress(o.out, todo.size(), "sample");
    std::size_t reported = 0;
    long n = 0;
    ranks::DriveOptions d;
    d.run = [&](int i) {
      const auto t0 = std::chrono::steady_clock::now();
      ++n;
      try
        {
          std::string block;
          for (const auto &r : solve_sample(cycle, in, dev, i, o.post))
            block += line(r) + '\n';
          j << block << std::flush; // one write per sample: a sample is in the journal whole or not
        }
      catch (const SolverError &e)
        {
          // A sample the cycle cannot serve is recorded and the study goes on (like a failed
          // batch job): failed.rank<r>.csv names it and the reason.
          const auto file = o.output_dir / ("failed.rank" + std::to_string(mpi.rank()) + ".csv");
          std::ofstream f(file, std::ios::app);
          std::string why = e.what();
          std::replace(why.begin(), why.end(), '\n', ' ');
          std::replace(why.begin(), why.end(), '"', '\'');
          f << i << ",\"" << why << "\"\n" << std::flush;
          return ranks::JobDone{false, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()};
        }
      return ranks::JobDone{true, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()};
    };
    d.finished = [&](int i, const ranks::JobDone &r, int rank) {
      progress.step(++reported, "sample " + std::to_string(i) + " on rank " + std::to_string(rank) +
                                  (r.ok ? "" : ": failed (failed.rank" + std::to_string(rank) + ".csv)"));
    };
    // A sample makes no MPI call: rank 0 works beside its manager thread with any thread level.
    d.local_worker = true;
    ranks::drive(mpi, todo, d);
    return n;
  }

  std::vector<SampleResult> merge_samples(const std::filesystem::path &dir, long samples, std::size_t n_torques)
  {
    const auto all = read_journals(dir, n_torques);
    std::vector<SampleResult> out;
    for (const auto &[k, v] : all)
      if (k < samples)
        out.insert(out.end(), v.begin(), v.end());
    std::sort(out.begin(), out.end(), [](const SampleResult &a, const SampleResult &b) {
      return a.torque != b.torque ? a.torque < b.torque : a.sample < b.sample;
    });
    AtomicOutputFile f(dir / "samples.csv");
    f << "sample [-],torque [N m],p-p STE [um],mean STE [um],mesh order 1 [um],mesh order 2 [um],mesh order 3 [um],"
         "largest non-mesh order [um],its order [-],max root stress pinion [MPa],max root stress gear [MPa],max "
         "pressure [MPa],max |f_pt| pinion [um],max |f_pt| gear [um],F_p span pinion [um],F_p span gear [um],F_r "
         "pinion [um],F_r gear [um]\n";
    f.stream() << std::setprecision(10);
    for (const auto &r : out)
      f << r.sample << ',' << r.torque << ',' << r.pp_ste * 1e6 << ',' << r.mean_ste * 1e6 << ',' << r.mesh[0] * 1e6
        << ',' << r.mesh[1] * 1e6 << ',' << r.mesh[2] * 1e6 << ',' << r.other * 1e6 << ',' << r.other_order << ','
        << r.root[0] * 1e-6 << ',' << r.root[1] * 1e-6 << ',' << r.p_max * 1e-6 << ',' << r.f_pt_max[0] * 1e6 << ','
        << r.f_pt_max[1] * 1e6 << ',' << r.F_p_span[0] * 1e6 << ',' << r.F_p_span[1] * 1e6 << ',' << r.F_r[0] * 1e6
        << ',' << r.F_r[1] * 1e6 << '\n';
    f.commit();
    return out;
  }

  std::vector<Statistic> statistics(const std::vector<SampleResult> &samples)
  {
    struct Figure
    {
      const char *name, *unit;
      double scale;
      double (*get)(const SampleResult &);
    };
    static const Figure figures[] = {
      {"p-p STE", "um", 1e6, [](const SampleResult &r) { return r.pp_ste; }},
      {"mean STE", "um", 1e6, [](const SampleResult &r) { return r.mean_ste; }},
      {"mesh order 1", "um", 1e6, [](const SampleResult &r) { return r.mesh[0]; }},
      {"mesh order 2", "um", 1e6, [](const SampleResult &r) { return r.mesh[1]; }},
      {"mesh order 3", "um", 1e6, [](const SampleResult &r) { return r.mesh[2]; }},
      {"largest non-mesh order", "um", 1e6, [](const SampleResult &r) { return r.other; }},
      {"max root stress pinion", "MPa", 1e-6, [](const SampleResult &r) { return r.root[0]; }},
      {"max root stress gear", "MPa", 1e-6, [](const SampleResult &r) { return r.root[1]; }},
      {"max pressure", "MPa", 1e-6, [](const SampleResult &r) { return r.p_max; }},
    };
    std::set<double> torques;
    for (const auto &s : samples)
      torques.insert(s.torque);
    std::vector<Statistic> out;
    for (const double T : torques)
      for (const auto &f : figures)
        {
          std::vector<double> v;
          for (const auto &s : samples)
            if (s.torque == T)
              v.push_back(f.get(s) * f.scale);
          std::sort(v.begin(), v.end());
          Statistic st;
          st.name = f.name, st.unit = f.unit, st.torque = T, st.n = v.size();
          if (v.empty())
            continue;
          double sum = 0, sum2 = 0;
          for (const double x : v)
            sum += x;
          st.mean = sum / double(v.size());
          for (const double x : v)
            sum2 += (x - st.mean) * (x - st.mean);
          st.standard_error = v.size() > 1 ? std::sqrt(sum2 / double(v.size() - 1) / double(v.size())) : 0.0;
          st.p5 = percentile(v, 0.05), st.p50 = percentile(v, 0.5), st.p95 = percentile(v, 0.95);
          st.min = v.front(), st.max = v.back();
          out.push_back(st);
        }
    return out;
  }

  void write_statistics(const std::vector<Statistic> &stats, const std::filesystem::path &file)
  {
    AtomicOutputFile f(file);
    f << "figure,unit,torque [N m],samples [-],mean,standard error of the mean,5 %,50 %,95 %,min,max\n";
    f.stream() << std::setprecision(8);
    for (const auto &s : stats)
      f << '"' << s.name << "\"," << s.unit << ',' << s.torque << ',' << s.n << ',' << s.mean << ','
        << s.standard_error << ',' << s.p5 << ',' << s.p50 << ',' << s.p95 << ',' << s.min << ',' << s.max << '\n';
    f.commit();
  }

  std::string statistics_table(const std::vector<Statistic> &stats)
  {
    std::ostringstream s;
    s << "| T1 [N m] | figure | mean ± standard error | 5 % | 50 % | 95 % | samples |\n|---|---|---|---|---|---|---|\n";
    s << std::setprecision(4);
    for (const auto &st : stats)
      s << "| " << st.torque << " | " << st.name << " [" << st.unit << "] | " << st.mean << " ± " << st.standard_error
        << " | " << st.p5 << " | " << st.p50 << " | " << st.p95 << " | " << st.n << " |\n";
    return s.str();
  }

  void check_study_input(const solve::GearContactInput &in, const DeviationParameters &dev)
  {
    if (dev.grade == 0)
      throw InputError("Deviations/Accuracy grade", "0", "1 .. 11",
                       "a tolerance study draws its samples within an ISO 1328-1 grade");
    check_one_pitch_cycle(in);
    condensed::check_condensable(in);
    (void)resolve_deviations(dev, *in.pair, 0); // the grade's range of application
  }

  std::string tolerance_table(const solve::GearContactInput &in, int grade)
  {
    std::ostringstream s;
    s << "| gear | f_pT | F_pT | f_HaT | f_faT | F_rT |\n|---|---|---|---|---|---|\n" << std::setprecision(4);
    for (int b = 1; b <= 2; ++b)
      {
        const auto &g  = in.pair->gear(b);
        const double m = g.parameters().rack.module;
        const auto t   = geometry::iso1328_tolerances(grade, m, m * g.teeth(), g.parameters().face_width);
        s << "| " << b << " | " << t.f_pT * 1e6 << " | " << t.F_pT * 1e6 << " | " << t.f_HaT * 1e6 << " | "
          << t.f_faT * 1e6 << " | " << t.F_rT * 1e6 << " |\n";
      }
    return s.str() + "(um; ISO 1328-1:2013, grade " + std::to_string(grade) + ")\n";
  }

  condensed::CondensedCycle study_cycle(const solve::GearContactInput &in, std::ostream *out)
  {
    const condensed::CycleRange range = condensed::cycle_range(in.solve.torques, condensed::CycleUse::variants);
    auto model                        = in.model();
    if (out)
      *out << "condensed cycle: building it (" << model->n_dofs() << " DoFs) for " << range.lo << " .. "
           << range.hi << " N m" << std::endl;
    condensed::CycleOptions options;
    options.out = out;
    return condensed::cycle_for(*model, in, range, options);
  }

  StudySummary summarise_study(const std::filesystem::path &output_dir, const solve::GearContactInput &in,
                               const DeviationParameters &dev, long samples)
  {
    StudySummary sum;
    const std::size_t n_torques = in.solve.torques.size();
    const auto merged           = merge_samples(output_dir, samples, n_torques);
    sum.statistics              = statistics(merged);
    write_statistics(sum.statistics, output_dir / "statistics.csv");
    sum.failed   = failed_samples(output_dir);
    sum.complete = merged.size() / std::max<std::size_t>(1, n_torques);
    write_file_atomically(output_dir / "summary.md",
                          "# Tolerance study\n\n" + tolerance_table(in, dev.grade) + "\n" +
                            statistics_table(sum.statistics) +
                            "\nfailed samples (not in the statistics; failed.rank*.csv): " +
                            std::to_string(sum.failed.size()) + "\n");
    return sum;
  }
} // namespace gearfem::deviations
