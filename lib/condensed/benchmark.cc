// The condensed-cycle benchmark.
#include "condensed/benchmark.h"
#include "base/progress.h"

#include "base/errors.h"
#include "base/memory.h"
#include "condensed/cycle.h"
#include "condensed/resolve.h"
#include "post/parameters.h"
#include "post/position.h"
#include "solve/input.h"

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <cmath>
#include <iomanip>
#include <list>
#include <sstream>

namespace gearfem::condensed
{
  namespace
  {
    using Clock = std::chrono::steady_clock;

    solve::GearContactInput parse(const std::string &text)
    {
      dealii::ParameterHandler prm;
      solve::declare_gear_contact_input(prm);
      post::declare_post_parameters(prm);
      prm.parse_input_from_string(text, "", true);
      return solve::parse_gear_contact_input(prm);
    }
  } // namespace

  void benchmark(const std::filesystem::path &prm_file, std::ostream &out)
  {
    if (!std::filesystem::is_regular_file(prm_file))
      throw InputError("input file", prm_file.string(), "an existing readable file");
    std::ostringstream text;
    text << std::ifstream(prm_file).rdbuf();
    // The case on the gap route (a relief is then a gap, and the variants share the mesh).
    const std::string base = text.str() + "\nsubsection Contact\n  set Micro-geometry = gap\nend\n";
    const solve::GearContactInput in = parse(base);
    check_condensable(in);
    const double T = in.solve.torques.front();
    auto model     = in.model();
    const double setup = model->setup_seconds();
    auto t0            = Clock::now();
    const CondensedCycle cycle = cycle_for(*model, in, cycle_range({T / 4, T, 4 * T}, CycleUse::given_torques));
    const double build = since(t0);
    std::size_t scenes = 0, m = 0;
    for (const auto &ps : cycle.cycle)
      for (const auto &p : ps)
        ++scenes, m = std::max(m, p.size());
    out << "condensed benchmark: " << prm_file.filename().string() << ", " << model->n_dofs() << " DoFs, "
        << cycle.positions.size() << " positions, cycle built at " << T << " N m (range " << T / 4 << " to "
        << 4 * T << " N m): set-up " << std::setprecision(3) << setup << " s, build " << build << " s, "
        << scenes << " scenes, up to " << m << " candidates\n\n"
        << "| variant | full FE [ms/pos] | condensed [ms/pos] | ratio | max STE diff [%] | max root stress diff "
           "[%] | max load share diff [-] |\n|---|---|---|---|---|---|---|\n";
    const std::string relief = "subsection Gear 1\n  set Tip relief = linear\n  set Tip relief amount = 10\n"
                               "  set Tip relief length = 6.7\nend\nsubsection Gear 2\n  set Tip relief = linear\n"
                               "  set Tip relief amount = 10\n  set Tip relief length = 6.7\nend\n";
    const post::PostOptions po;
    struct Variant
    {
      std::string name;
      double torque;
      std::string extra;
    };
    // The model points to the pair of the variant it was last re-targeted to: keep them all.
    std::list<solve::GearContactInput> variants;
    for (const Variant &v : {Variant{"T/2", T / 2, ""}, Variant{"2 T", 2 * T, ""},
                             Variant{"T, 10 um long relief", T, relief}})
      {
        const solve::GearContactInput &vin = variants.emplace_back(parse(base + v.extra));
        const Resolver resolver(cycle, vin);
        model->set_micro_geometry(*vin.pair);
        double t_full = 0, t_cond = 0, d_ste = 0, d_root = 0, d_share = 0;
        const contact::ContactSolution *warm = nullptr;
        contact::ContactState full;
        for (std::size_t k = 0; k < cycle.positions.size(); ++k)
          {
            t0                   = Clock::now();
            full                 = model->solve(cycle.positions[k].second, v.torque, warm);
            const auto fr        = post::evaluate_position(*model, full, po);
            t_full += since(t0);
            warm                 = &full.solution;
            t0                   = Clock::now();
            const Resolved c     = resolver.solve(resolver.positions()[k], v.torque, po);
            t_cond += since(t0);
            d_ste  = std::max(d_ste, std::abs(c.result.ste - fr.ste) / fr.ste);
            d_root = std::max({d_root, std::abs(c.result.max_root_stress_pinion - fr.max_root_stress_pinion) /
                                         fr.max_root_stress_pinion,
                               std::abs(c.result.max_root_stress_gear - fr.max_root_stress_gear) /
                                 fr.max_root_stress_gear});
            for (std::size_t i = 0; i < std::min(c.result.pairs.size(), fr.pairs.size()); ++i)
              d_share = std::max(d_share, std::abs(c.result.pairs[i].share - fr.pairs[i].share));
            if (c.result.pairs.size() != fr.pairs.size())
              d_share = 1;
          }
        const double n = double(cycle.positions.size());
        out << "| " << v.name << " | " << std::setprecision(4) << 1e3 * t_full / n << " | " << 1e3 * t_cond / n
            << " | " << t_full / t_cond << " | " << std::setprecision(3) << 100 * d_ste << " | " << 100 * d_root
            << " | " << d_share << " |" << std::endl;
      }
    out << "\npeak memory " << peak_memory_mb() << " MB\n"
        << "full FE: search, linearisation, contact solve and post (displacement fields, fillet stresses) per "
           "position, warm-started; condensed: the stored problem and the influence coefficients.\n"
           "Targets: condensed <= 1 ms per position with stresses; STE within 0.1 %, root stress within 0.5 %, "
           "load share within 0.002 of the full FE.\n";
  }
} // namespace gearfem::condensed
