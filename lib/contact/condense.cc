// TwoBodyContact::condense: the condensed problem of a converged configuration
// (contact/condensed.h), re-linearised at the solution's state.
#include "contact/condensed.h"
#include "contact/two_body.h"

#include "base/errors.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace gearfem::contact
{
  /// Edges of the stored set: a candidate next to a slave node of the scene that is not a
  /// candidate (the re-solve checks how far their contact may close).
  void TwoBodyContact::mark_edges(const Scene &scene, const SearchResult &sr, CondensedPosition &out) const
  {
    std::set<int> is_candidate, is_slave;
    for (const auto &c : sr.cand)
      is_candidate.insert(key(c.S, c.node));
    for (const auto &[b, n] : slaves(scene))
      is_slave.insert(key(b, n));
    for (std::size_t k = 0; k < sr.cand.size(); ++k)
      {
        const auto &c = sr.cand[k];
        for (const int f : cache_[c.S - 1].node_faces[c.node])
          for (const int n : surface(c.S).faces()[f].nodes)
            if (is_slave.count(key(c.S, n)) && !is_candidate.count(key(c.S, n)))
              out.cand[k].edge = true;
      }
  }

  CondensedPosition TwoBodyContact::condense(const Scene &scene, const ContactSolution &solution, double band)
  {
    if (!solution.converged)
      throw SolverError("condense: the solution to condense did not converge");
    if (options_.friction > 0)
      throw InputError("Contact/Friction coefficient", to_string_g(options_.friction),
                       "0 for a condensed cycle", "the condensed cycle stores the frictionless operator");
    const double q = solution.q;
    // The band of the loads the cycle serves: candidates farther open never touch there, so
    // the searches below look no farther (the solver's search distance is restored on return).
    const bool banded = band > 0 && band < options_.search_distance;
    struct Restore
    {
      double &value;
      const double kept;
      ~Restore() { value = kept; }
    } restore{options_.search_distance, options_.search_distance};
    if (banded)
      options_.search_distance = band;
    // The elastic state of the solution, from its nodal forces, on a zone with twice the
    // solve's margin (the searches at q -/+ h below stay inside it).
    set_zone(scene, q, 2 * options_.search_distance);
    std::vector<std::pair<int, double>> forces[2];
    for (int b = 0; b < 2; ++b)
      for (const auto &[d, f] : solution.forces[b])
        forces[b].emplace_back(cache_[b].index[d], f);
    double t_columns = 0;
    set_displacements(forces, t_columns);
    std::vector<double> lambda_node(s1_->nodes().size() + s2_->nodes().size(), 0.0);
    for (const auto &p : solution.points)
      lambda_node[key(p.slave_body, p.node)] = p.force;

    const SearchResult sr = search(scene, q);
    const int m           = int(sr.cand.size());
    if (m == 0)
      throw SolverError("condense: no candidate slave node at the solution");
    double t_flex = 0;
    const Linearisation lin = linearise(scene, sr, q, lambda_node, t_flex, true);

    CondensedPosition out;
    out.q_build    = q;
    out.search_distance = banded ? band : options_.search_distance;
    out.load_build = solution.load;
    out.placement[0] = scene.placement[0], out.placement[1] = scene.placement[1];
    out.W = lin.W, out.a = lin.a, out.D = lin.D;
    out.B[0] = lin.B[0], out.B[1] = lin.B[1];

    // Curvature of each candidate's gap in q at the solution's elastic state: central
    // difference of the exact placement over half the build rotation (a secant over the
    // range of loads a cycle is re-solved at), matched by slave node.
    out.curvature = Eigen::VectorXd::Zero(m);
    const double h = std::max(0.5 * std::abs(q), 1e-7);
    std::map<int, double> g_plus, g_minus;
    std::vector<char> smooth(m, 1);
    // In a band, the searches at q -/+ h reach as far as the rotation by h moves a point, so
    // that they find every candidate of the band and its curvature is the unbanded one.
    if (banded)
      options_.search_distance = band + h * (drive_.kind == Drive::Kind::rotation ? cache_[0].r_max : 1.0);
    for (const auto &c : search(scene, q + h).cand)
      g_plus[key(c.S, c.node)] = c.g;
    for (const auto &c : search(scene, q - h).cand)
      g_minus[key(c.S, c.node)] = c.g;
    options_.search_distance = banded ? band : restore.kept;
    if (zone_breach_)
      throw SolverError("condense: a projection reads the elastic state outside the contact zone");
    for (int k = 0; k < m; ++k)
      {
        const int kk = key(sr.cand[k].S, sr.cand[k].node);
        const auto p = g_plus.find(kk), n = g_minus.find(kk);
        if (p != g_plus.end() && n != g_minus.end())
          out.curvature[k] = (p->second - 2 * sr.cand[k].g + n->second) / (h * h);
        else
          smooth[k] = false;
        if (std::abs(out.curvature[k] * h) > 0.1 * std::abs(lin.a[k]))
          smooth[k] = false;
        if (!smooth[k])
          out.curvature[k] = 0;
      }

    // Where the gap modifications enter each gap, and the unmodified gap.
    out.modification.assign(m, {});
    out.ghat = lin.ghat;
    for (int k = 0; k < m; ++k)
      {
        const auto &c = sr.cand[k];
        const int S = c.S, M = 3 - S;
        auto &ms      = out.modification[k];
        if (c.terms.empty())
          {
            ms.push_back({S, surface(S).nodes()[c.node].x, 1.0});
            ms.push_back({M, c.at.pr.point, 1.0});
          }
        else
          for (const auto &[i, coef] : c.terms)
            {
              ms.push_back({S, sr.samples[i].gp.x, coef});
              ms.push_back({M, sr.samples[i].gp.pr.point, coef});
            }
        for (const auto &s : ms)
          out.ghat[k] -= s.weight * gap_offset(s.body, s.x);
      }

    // The converged forces on the candidates, their gaps and the contact points.
    Eigen::VectorXd lambda(m), gap(m);
    for (int k = 0; k < m; ++k)
      lambda[k] = lambda_node[key(sr.cand[k].S, sr.cand[k].node)];
    gap = lin.ghat + lin.a * q + lin.W * lambda;
    ContactSolution filled;
    fill_solution(filled, sr.cand, lin, lambda, gap, scene, q);
    out.cand.resize(m);
    for (int k = 0; k < m; ++k)
      out.cand[k].point = filled.points[k], out.cand[k].smooth = smooth[k];

    mark_edges(scene, sr, out);

    // Pressure recovery as a linear map of the candidate forces.
    out.pressure.assign(m, {});
    for (int S = 1; S <= 2; ++S)
      {
        const auto &ss = surface(S);
        std::vector<int> at_node(ss.nodes().size(), -1);
        for (int k = 0; k < m; ++k)
          if (sr.cand[k].S == S)
            at_node[sr.cand[k].node] = k;
        std::vector<double> unit(ss.nodes().size(), 0.0);
        for (int j = 0; j < m; ++j)
          {
            if (sr.cand[j].S != S)
              continue;
            unit[sr.cand[j].node] = 1.0;
            const std::vector<double> p = ss.recover_pressure(unit, contact_width());
            unit[sr.cand[j].node] = 0.0;
            for (std::size_t n = 0; n < p.size(); ++n)
              if (p[n] != 0 && at_node[n] >= 0)
                out.pressure[at_node[n]].emplace_back(j, p[n]);
          }
      }
    return out;
  }
} // namespace gearfem::contact
