// The solve benchmark.
#include "contact/benchmark.h"

#include "base/errors.h"
#include "base/memory.h"
#include "contact/parameters.h"

#include <deal.II/base/parameter_handler.h>


#include <chrono>
#include <iomanip>

namespace gearfem::contact
{
  void benchmark(const std::filesystem::path &prm_file, std::ostream &out)
  {
    if (!std::filesystem::is_regular_file(prm_file))
      throw InputError("input file", prm_file.string(), "an existing readable file");
    dealii::ParameterHandler prm;
    declare_gear_contact_input(prm);
    prm.parse_input(prm_file.string(), "", true, true); // other commands' sections are ignored
    GearContactInput in = parse_gear_contact_input(prm);
    const auto positions = in.positions();
    const double T       = in.solve.torques.front();
    out << "solve benchmark: " << prm_file.filename().string() << ", z " << in.pair->gear(1).teeth() << "/"
        << in.pair->gear(2).teeth() << ", h_contact " << mesh::contact_size(in.mesh[0], in.pair->gear(1).parameters().rack.module) * 1e3 << " mm, Q"
        << in.fe.degree << ", " << positions.size() << " positions at T1 = " << T << " N m\n\n"
        << "| method | DoFs | mesh [s] | set-up [s] | search [s/pos] | flexibility [s/pos] | contact solve "
           "[s/pos] | post [s/pos] | total [s/pos] | sweep [s] | geometry it/pos | active-set it/pos | "
           "mean STE [um] | peak memory [MB] |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Method m : {Method::lagrange, Method::penalty})
      {
        in.contact.method = m;
        auto model        = in.model();
        double ts = 0, tc = 0, tl = 0, tp = 0, tt = 0, ste = 0;
        long git = 0, ait = 0;
        PositionResult prev;
        bool have = false;
        const auto t0 = std::chrono::steady_clock::now();
        for (const auto &[name, phi] : positions)
          {
            auto r = model->solve(phi, T, have ? &prev : nullptr);
            ts += r.t_search, tc += r.t_compliance, tl += r.t_solve, tp += r.t_post, tt += r.t_total;
            git += r.solution.geometry_iterations, ait += r.solution.active_set_iterations;
            ste += r.ste;
            prev = std::move(r), have = true;
          }
        const double sweep = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const double n     = double(positions.size());
        out << std::fixed << std::setprecision(3) << "| " << to_string(m) << " | " << model->n_dofs() << " | "
            << model->mesh_seconds() << " | " << model->setup_seconds() << " | " << ts / n << " | " << tc / n
            << " | " << tl / n << " | " << tp / n << " | " << tt / n << " | " << std::setprecision(2) << sweep
            << " | " << git / n << " | " << ait / n << " | " << std::setprecision(4) << ste / n * 1e6 << " | "
            << std::setprecision(0) << peak_memory_mb() << " |" << std::endl;
      }
    out << std::defaultfloat
        << "\nflexibility: block solves for the contact DoFs not yet cached (the first positions pay most);"
           "\nset-up: meshing, assembly and factorisation of both gears (once per run).\n"
           "Targets (2-core machine, mesh level with <= 1 % STE error): <= 5 s per position, <= 3 min per "
           "40-position cycle.\n";
  }
} // namespace gearfem::contact
