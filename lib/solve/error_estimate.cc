#include "solve/error_estimate.h"
#include "base/units.h"

#include "base/errors.h"
#include "base/progress.h"
#include "post/observers.h"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace gearfem::solve
{
  using post::EvaluatingObserver;
  using post::Evaluator;
  using post::PositionObserver;
  using post::PositionResult;
  using post::PostOptions;

  namespace
  {
    using Clock     = std::chrono::steady_clock;


    EstimatedQuantities quantities(const PositionResult &r)
    {
      EstimatedQuantities q;
      q.ste                = r.ste;
      q.root_stress_pinion = r.max_root_stress_pinion;
      q.root_stress_gear   = r.max_root_stress_gear;
      q.p_max              = r.p_max;
      return q;
    }

    /// Solve and evaluate one position; `warm` is updated to the converged solution.
    EstimatedQuantities solve_one(contact::GearContactModel &model, double phi1, double T,
                                  contact::ContactSolution &warm, bool &have_warm, const PostOptions &post)
    {
      const contact::ContactState s = model.solve(phi1, T, have_warm ? &warm : nullptr);
      if (!s.solution.converged)
        throw SolverError("error estimate: the contact solve at roll " + to_string_g(phi1 / units::deg) +
                          " deg, T1 " + to_string_g(T) + " N m did not converge");
      warm      = s.solution;
      have_warm = true;
      const EstimatedQuantities q = quantities(post::evaluate_position(model, s, post));
      for (int i = 0; i < EstimatedQuantities::size; ++i)
        if (!std::isfinite(q[i]))
          throw SolverError(std::string("error estimate: non-finite ") + EstimatedQuantities::names()[i] +
                            " at roll " + to_string_g(phi1 / units::deg) + " deg");
      return q;
    }

    /// Richardson: e_h = (Q_{h/r} - Q_h) r^p / (r^p - 1), and its size relative to Q_h.
    void richardson(ErrorSample &s, double r, double p)
    {
      const double f = std::pow(r, p) / (std::pow(r, p) - 1);
      for (int i = 0; i < EstimatedQuantities::size; ++i)
        {
          s.error[i]    = (s.fine[i] - s.coarse[i]) * f;
          s.relative[i] = s.coarse[i] != 0 ? std::abs(s.error[i] / s.coarse[i]) : 0.0;
        }
    }

    void collect_maxima(ErrorEstimate &e, const std::vector<double> &torques)
    {
      for (const double T : torques)
        {
          EstimatedQuantities a, rel;
          for (const auto &s : e.samples)
            if (s.torque == T)
              for (int i = 0; i < EstimatedQuantities::size; ++i)
                {
                  a[i]   = std::max(a[i], std::abs(s.error[i]));
                  rel[i] = std::max(rel[i], s.relative[i]);
                }
          e.max_error.emplace_back(T, a);
          e.max_relative.emplace_back(T, rel);
        }
    }

    std::string json_number(double v)
    {
      std::ostringstream o;
      o << std::setprecision(12) << (std::isfinite(v) ? v : 0.0);
      return o.str();
    }
  } // namespace

  double EstimatedQuantities::operator[](int i) const
  {
    return i == 0 ? ste : i == 1 ? root_stress_pinion : i == 2 ? root_stress_gear : p_max;
  }

  double &EstimatedQuantities::operator[](int i)
  {
    return i == 0 ? ste : i == 1 ? root_stress_pinion : i == 2 ? root_stress_gear : p_max;
  }

  const std::array<const char *, EstimatedQuantities::size> &EstimatedQuantities::names()
  {
    static const std::array<const char *, size> n = {"STE_um", "root_stress_pinion_MPa", "root_stress_gear_MPa",
                                                     "p_max_MPa"};
    return n;
  }

  const std::array<double, EstimatedQuantities::size> &EstimatedQuantities::output_factors()
  {
    static const std::array<double, size> f = {1e6, 1e-6, 1e-6, 1e-6};
    return f;
  }

  std::vector<std::array<std::string, 2>> error_sample_names()
  {
    return {{"single pair", "(B+D)/2"}, {"double pair", "(A+B)/2"}, {"transition", "D"}};
  }

  std::vector<double> error_sample_positions(const geometry::GearPair &pair)
  {
    const double A = pair.point("A").roll_angle, B = pair.point("B").roll_angle, D = pair.point("D").roll_angle;
    return {0.5 * (B + D), 0.5 * (A + B), D};
  }

  mesh::GearMeshParameters refined_mesh(const mesh::GearMeshParameters &p, double module, double refinement)
  {
    if (!(refinement > 1))
      throw InputError("error estimate refinement", to_string_g(refinement), "> 1");
    mesh::GearMeshParameters f = p;
    f.h_contact                = mesh::contact_size(p, module) / refinement;
    f.h_fillet                 = p.h_fillet / refinement;
    f.h_coast                  = p.h_coast / refinement;  // 0 stays 0: follows h_fillet
    f.h_corner                 = p.h_corner / refinement; // 0 stays 0: h_contact/4
    f.validate();
    return f;
  }

  std::vector<EstimatedQuantities> solve_samples(contact::GearContactModel &model, const std::vector<double> &positions,
                                                 const std::vector<double> &torques, const post::PostOptions &post,
                                                 Progress *progress, std::size_t step, const std::string &label)
  {
    std::vector<EstimatedQuantities> q;
    std::vector<contact::ContactSolution> warm(positions.size());
    std::vector<char> have(positions.size(), 0);
    for (const double T : torques)
      for (std::size_t i = 0; i < positions.size(); ++i)
        {
          bool h = have[i];
          q.push_back(solve_one(model, positions[i], T, warm[i], h, post));
          have[i] = h;
          if (progress)
            {
              std::ostringstream d;
              d << "T " << T << " N m, roll " << std::fixed << std::setprecision(3) << positions[i] / units::deg
                << " deg" << (label.empty() ? "" : ", " + label) << ", STE " << q.back().ste * 1e6 << " um";
              progress->step(++step, d.str());
            }
        }
    return q;
  }

  ErrorEstimate estimate_error(contact::GearContactModel &coarse, contact::GearContactModel &fine,
                               const std::vector<double> &positions, const std::vector<double> &torques,
                               const ErrorEstimateOptions &options)
  {
    if (!(options.order > 0))
      throw InputError("error estimate order", to_string_g(options.order), "> 0");
    if (!(options.refinement > 1))
      throw InputError("error estimate refinement", to_string_g(options.refinement), "> 1");
    ErrorEstimate e;
    e.refinement = options.refinement;
    e.order      = options.order;
    e.fine_dofs  = fine.n_dofs();
    const auto t0 = Clock::now();
    Progress progress(options.out, 2 * positions.size() * torques.size(), "error-estimate solve");
    const std::size_t n = positions.size() * torques.size();
    const auto coarse_q = solve_samples(coarse, positions, torques, options.post, &progress, 0, "level h");
    const auto fine_q   = solve_samples(fine, positions, torques, options.post, &progress, n, "level h/r");
    for (std::size_t t = 0; t < torques.size(); ++t)
      for (std::size_t i = 0; i < positions.size(); ++i)
        {
          ErrorSample s;
          s.phi1   = positions[i];
          s.torque = torques[t];
          s.coarse = coarse_q[t * positions.size() + i];
          s.fine   = fine_q[t * positions.size() + i];
          richardson(s, e.refinement, e.order);
          e.samples.push_back(s);
        }
    e.seconds_solve = since(t0);
    collect_maxima(e, torques);
    return e;
  }

  ErrorEstimate estimate_error(contact::GearContactModel &model, const solve::GearContactInput &in,
                               const ErrorEstimateOptions &options)
  {
    in.require_external("Solve/Error estimate");
    const auto t0 = Clock::now();
    mesh::GearMeshParameters mesh[2];
    for (int i = 0; i < 2; ++i)
      mesh[i] = refined_mesh(in.mesh[i], in.pair->gear(i + 1).parameters().rack.module, options.refinement);
    if (options.out)
      *options.out << "error estimate: building the refined model (fine mesh sizes / " << options.refinement
                   << ", h_contact " << mesh[0].h_contact * 1e3 << " mm)" << std::endl;
    contact::GearContactModel fine(*in.pair, mesh, in.material, in.fe, in.contact, in.unmodified_pair.get());
    const double setup = since(t0);
    if (options.out)
      *options.out << "error estimate: refined model " << fine.n_dofs() << " DoFs (run: " << model.n_dofs()
                   << "), set-up " << std::setprecision(3) << setup << " s" << std::endl;
    ErrorEstimate e = estimate_error(model, fine, error_sample_positions(*in.pair), in.solve.torques, options);
    e.seconds_setup  = setup;
    e.h_contact_fine = mesh[0].h_contact;
    const auto names = error_sample_names();
    for (std::size_t k = 0; k < e.samples.size(); ++k)
      e.samples[k].zone = names[k % names.size()][0], e.samples[k].point = names[k % names.size()][1];
    return e;
  }

  std::string error_estimate_table(const ErrorEstimate &e)
  {
    // Each number through its own stream: no formatting state leaks from one to the next.
    auto fixed = [](double v, int digits, bool sign = false) {
      std::ostringstream o;
      o << std::fixed << std::setprecision(digits) << (sign ? std::showpos : std::noshowpos) << v;
      return o.str();
    };
    auto general = [](double v) {
      std::ostringstream o;
      o << std::setprecision(6) << v;
      return o.str();
    };
    std::ostringstream o;
    o << "Estimated discretisation error of the run's mesh (Richardson, refinement " << general(e.refinement)
      << ", assumed order " << general(e.order) << "; Q_exact - Q_h, and |.| in % of Q_h):\n\n"
      << "| T1 [N m] | sample | roll [deg] | STE [um] | error STE [um] | root stress pinion [MPa] | error | "
         "root stress gear [MPa] | error | p_max [MPa] | error |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
    const auto &f = EstimatedQuantities::output_factors();
    for (const auto &s : e.samples)
      {
        o << "| " << general(s.torque) << " | " << (s.zone.empty() ? "" : s.zone + " " + s.point) << " | "
          << fixed(s.phi1 / units::deg, 3);
        for (int i = 0; i < EstimatedQuantities::size; ++i)
          o << " | " << fixed(s.coarse[i] * f[i], i == 0 ? 4 : 2) << " | "
            << fixed(s.error[i] * f[i], i == 0 ? 4 : 2, true) << " (" << fixed(100 * s.relative[i], 2) << " %)";
        o << " |\n";
      }
    o << "\nLargest estimated error over the samples:";
    for (std::size_t k = 0; k < e.max_relative.size(); ++k)
      {
        const auto &rel = e.max_relative[k].second;
        o << " T1 " << general(e.max_relative[k].first) << " N m: STE " << fixed(100 * rel.ste, 2)
          << " %, root stress pinion/gear " << fixed(100 * rel.root_stress_pinion, 2) << " / "
          << fixed(100 * rel.root_stress_gear, 2) << " %, p_max " << fixed(100 * rel.p_max, 2) << " %"
          << (k + 1 < e.max_relative.size() ? ";" : ".");
      }
    o << "\nCost: refined model (" << e.fine_dofs << " DoFs) " << fixed(e.seconds_setup, 1)
      << " s, sample solves " << fixed(e.seconds_solve, 1) << " s.\n";
    return o.str();
  }

  std::string error_estimate_json(const ErrorEstimate &e, const std::vector<std::pair<std::string, double>> &extra)
  {
    const auto &f = EstimatedQuantities::output_factors();
    const auto &n = EstimatedQuantities::names();
    std::ostringstream o;
    o << "{\n    \"method\": \"Richardson, e_h = (Q_h/r - Q_h) r^p/(r^p - 1)\",\n    \"refinement\": "
      << json_number(e.refinement) << ",\n    \"order\": " << json_number(e.order)
      << ",\n    \"h_contact_fine_mm\": " << json_number(e.h_contact_fine * 1e3) << ",\n    \"fine_dofs\": "
      << e.fine_dofs << ",\n    \"seconds_setup\": " << json_number(e.seconds_setup)
      << ",\n    \"seconds_solve\": " << json_number(e.seconds_solve);
    for (const auto &[name, v] : extra)
      o << ",\n    \"" << name << "\": " << json_number(v);
    o << ",\n    \"samples\": [";
    for (std::size_t k = 0; k < e.samples.size(); ++k)
      {
        const auto &s = e.samples[k];
        o << (k ? "," : "") << "\n      {\"zone\": \"" << s.zone << "\", \"point\": \"" << s.point
          << "\", \"roll_deg\": " << json_number(s.phi1 / units::deg) << ", \"torque_Nm\": " << json_number(s.torque);
        for (int i = 0; i < EstimatedQuantities::size; ++i)
          o << ",\n       \"" << n[i] << "\": {\"h\": " << json_number(s.coarse[i] * f[i])
            << ", \"h_over_r\": " << json_number(s.fine[i] * f[i]) << ", \"error\": " << json_number(s.error[i] * f[i])
            << ", \"relative\": " << json_number(s.relative[i]) << "}";
        o << "}";
      }
    o << "\n    ],\n    \"max\": [";
    for (std::size_t k = 0; k < e.max_error.size(); ++k)
      {
        o << (k ? "," : "") << "\n      {\"torque_Nm\": " << json_number(e.max_error[k].first);
        for (int i = 0; i < EstimatedQuantities::size; ++i)
          o << ", \"" << n[i] << "\": {\"error\": " << json_number(e.max_error[k].second[i] * f[i])
            << ", \"relative\": " << json_number(e.max_relative[k].second[i]) << "}";
        o << "}";
      }
    o << "\n    ]\n  }";
    return o.str();
  }
} // namespace gearfem::solve
