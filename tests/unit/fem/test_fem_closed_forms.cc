// FEM module against closed-form elasticity solutions (plane stress):
// Lame thick cylinder, Timoshenko-Goodier cantilever, annulus torsion, rigid rotation.
#include "base/errors.h"
#include "base/units.h"
#include "fem/elastic_body.h"
#include "mesh/domain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

using namespace gearfem;
using dealii::Point;
using dealii::SymmetricTensor;
using dealii::Tensor;

namespace
{
  const double E = 200e9, nu = 0.3;

  fem::Elasticity steel(double b = 0.01)
  {
    fem::Elasticity m;
    m.youngs_modulus = E;
    m.poisson_ratio  = nu;
    m.thickness      = b;
    return m;
  }

  /// Lame thick cylinder under internal pressure p, plane stress (Timoshenko & Goodier
  /// 1970, sec. 28): sigma_r = A - B/r^2, sigma_t = A + B/r^2, A = p a^2/(b^2 - a^2),
  /// B = p a^2 b^2/(b^2 - a^2), u_r = ((1 - nu) A r + (1 + nu) B / r)/E.
  struct Lame
  {
    double a, b, p;
    double A() const { return p * a * a / (b * b - a * a); }
    double B() const { return p * a * a * b * b / (b * b - a * a); }
    Tensor<1, 2> u(const Point<2> &x) const
    {
      const double r = x.norm(), ur = ((1 - nu) * A() * r + (1 + nu) * B() / r) / E;
      Tensor<1, 2> v;
      v[0] = ur * x[0] / r;
      v[1] = ur * x[1] / r;
      return v;
    }
    SymmetricTensor<2, 2> stress(const Point<2> &x) const
    {
      const double r = x.norm(), sr = A() - B() / (r * r), st = A() + B() / (r * r);
      const double c = x[0] / r, s = x[1] / r;
      SymmetricTensor<2, 2> t;
      t[0][0] = sr * c * c + st * s * s;
      t[1][1] = sr * s * s + st * c * c;
      t[0][1] = (sr - st) * s * c;
      return t;
    }
  };

  struct Run
  {
    double h;
    fem::ErrorNorms e;
  };

  std::vector<Run> lame_study(unsigned degree, unsigned levels)
  {
    const Lame lame{0.01, 0.02, 100e6};
    const auto m = mesh::mesh_domain(mesh::annulus_domain(lame.a, lame.b, 0.003));
    std::vector<Run> runs;
    for (unsigned r = 0; r < levels; ++r)
      {
        fem::FeOptions o;
        o.degree      = degree;
        o.refinements = r;
        o.interior    = mesh::InteriorManifold::all;
        fem::ElasticBody body(m, steel(), o);
        body.constrain(mesh::boundary::outer); // exact displacement on the outer circle
        body.assemble_and_factorize();
        const auto f = body.traction_load(
          [&](const Point<2> &x) { return Tensor<1, 2>(lame.p * x / x.norm()); }, // pressure
          {mesh::boundary::bore});
        const auto u = body.solve(f, [&](const Point<2> &x) { return lame.u(x); });
        runs.push_back({0.003 / std::pow(2.0, r),
                        body.errors(u, [&](const Point<2> &x) { return lame.u(x); },
                                    [&](const Point<2> &x) { return lame.stress(x); })});
      }
    return runs;
  }

  double rate(double e0, double e1) { return std::log(e0 / e1) / std::log(2.0); }
} // namespace

// Reference: Lame closed form; theory: ||u - u_h||_L2 ~ h^(p+1), energy and stress ~ h^p
// (curved boundary represented by MappingQ(p) on exact-curve manifolds).
TEST(FemClosedForms, LameConvergenceRatesQ1Q2)
{
  for (unsigned p : {1u, 2u})
    {
      const auto runs = lame_study(p, p == 1 ? 4 : 3);
      for (std::size_t i = 1; i < runs.size(); ++i)
        {
          const double ru = rate(runs[i - 1].e.l2_displacement, runs[i].e.l2_displacement);
          const double rs = rate(runs[i - 1].e.l2_stress, runs[i].e.l2_stress);
          const double re = rate(runs[i - 1].e.h1_displacement, runs[i].e.h1_displacement);
          std::cout << "Lame Q" << p << " h " << runs[i].h << " m: L2(u) " << runs[i].e.l2_displacement
                    << " rate " << ru << ", L2(sigma) rate " << rs << ", energy rate " << re
                    << std::endl;
          if (i + 1 == runs.size())
            {
              EXPECT_NEAR(ru, p + 1.0, 0.2);
              EXPECT_NEAR(rs, double(p), 0.2);
              EXPECT_NEAR(re, double(p), 0.2);
            }
        }
    }
}

// Reference: Timoshenko & Goodier (1970) sec. 21, cantilever with parabolic end shear:
// u = -P x^2 y/(2EI) - nu P y^3/(6EI) + P y^3/(6IG) + (P L^2/(2EI) - P c^2/(2IG)) y,
// v = nu P x y^2/(2EI) + P x^3/(6EI) - P L^2 x/(2EI) + P L^3/(3EI), load end x = 0,
// built-in end x = L (exact displacement prescribed there). Tip deflection P L^3/(3EI).
TEST(FemClosedForms, TimoshenkoCantileverTipDeflection)
{
  const double L = 0.1, H = 0.01, c = H / 2, I = 2 * c * c * c / 3, P = 1e5; // P per unit thickness
  const double G = E / (2 * (1 + nu));
  auto u_exact = [&](const Point<2> &p) {
    const double x = p[0], y = p[1];
    Tensor<1, 2> u;
    u[0] = -P * x * x * y / (2 * E * I) - nu * P * y * y * y / (6 * E * I) +
           P * y * y * y / (6 * I * G) + (P * L * L / (2 * E * I) - P * c * c / (2 * I * G)) * y;
    u[1] = nu * P * x * y * y / (2 * E * I) + P * x * x * x / (6 * E * I) -
           P * L * L * x / (2 * E * I) + P * L * L * L / (3 * E * I);
    return u;
  };
  const double tip = P * L * L * L / (3 * E * I);
  const auto m     = mesh::mesh_domain(mesh::rectangle_domain(L, H, 0.002));
  double err       = 1;
  for (unsigned p : {1u, 2u})
    {
      fem::FeOptions o;
      o.degree      = p;
      o.refinements = 1;
      fem::ElasticBody body(m, steel(1.0), o);
      body.constrain(13); // x = L
      body.assemble_and_factorize();
      // Traction on x = 0 (normal -x): t = sigma n = (0, -tau_xy), tau_xy = -P (c^2 - y^2)/(2I).
      const auto f = body.traction_load(
        [&](const Point<2> &x) { return Tensor<1, 2>({0.0, P * (c * c - x[1] * x[1]) / (2 * I)}); },
        {11});
      const auto u = body.solve(f, u_exact);
      const double v = body.displacement_at(u, Point<2>(0, 0))[1];
      err            = std::abs(v - tip) / tip;
      std::cout << "cantilever Q" << p << ": tip " << v << " m, Timoshenko-Goodier " << tip
                << " m, error " << 100 * err << " %" << std::endl;
    }
  EXPECT_LT(err, 0.01);
}

// Reference: torsion of an annulus clamped at r = a with shear tau on r = b:
// torque T = 2 pi b^2 tau t, u_theta(r) = (T/(4 pi mu t)) (r/a^2 - 1/r) (plane stress and
// strain alike). Conservation: reaction moment = -applied moment to 1e-8.
TEST(FemClosedForms, AnnulusTorsionReactionTorque)
{
  const double a = 0.01, b = 0.02, tau = 10e6, t = 0.02;
  const auto m = mesh::mesh_domain(mesh::annulus_domain(a, b, 0.002));
  fem::FeOptions o;
  o.degree = 2;
  fem::ElasticBody body(m, steel(t), o);
  body.constrain(mesh::boundary::bore);
  body.assemble_and_factorize();
  const auto f = body.traction_load(
    [&](const Point<2> &x) { return Tensor<1, 2>({-tau * x[1] / x.norm(), tau * x[0] / x.norm()}); },
    {mesh::boundary::outer});
  const auto u      = body.solve(f);
  const double T    = 2 * gearfem::units::pi * b * b * tau * t;
  const double Tf   = body.moment(f);
  const double Tr   = body.moment(body.reactions(u, f));
  std::cout << "torsion: closed form " << T << " N m, load " << Tf << ", reaction " << Tr << std::endl;
  EXPECT_NEAR(Tf, T, 1e-5 * T); // quadrature on the Q2 image of the circle
  EXPECT_NEAR(Tr, -Tf, 1e-8 * T);
  const auto ut       = body.displacement_at(u, Point<2>(0, b));
  const double mu     = E / (2 * (1 + nu));
  const double ut_ref = T / (4 * gearfem::units::pi * mu * t) * (b / (a * a) - 1 / b);
  EXPECT_NEAR(-ut[0], ut_ref, 2e-3 * ut_ref);

  // MUMPS and UMFPACK give the same solution.
  fem::FeOptions om = o;
  om.solver         = fem::SolverKind::mumps;
  fem::ElasticBody body2(m, steel(t), om);
  body2.constrain(mesh::boundary::bore);
  body2.assemble_and_factorize();
  EXPECT_EQ(body2.solver_used(), fem::SolverKind::mumps);
  auto u2 = body2.solve(f);
  u2 -= u;
  EXPECT_LT(u2.linfty_norm(), 1e-10 * u.linfty_norm());
}

// Reference: a rigid rotation u = theta (-y, x) has zero strain, so zero stress
// (<= 1e-6 of E theta).
TEST(FemClosedForms, RigidRotationGivesZeroStress)
{
  const double theta = 1e-3;
  const auto m       = mesh::mesh_domain(mesh::annulus_domain(0.01, 0.02, 0.003));
  for (unsigned p : {1u, 2u})
    {
      fem::FeOptions o;
      o.degree = p;
      fem::ElasticBody body(m, steel(), o);
      body.constrain(mesh::boundary::bore);
      body.assemble_and_factorize();
      dealii::Vector<double> f(body.n_dofs());
      const auto u =
        body.solve(f, [&](const Point<2> &x) { return Tensor<1, 2>({-theta * x[1], theta * x[0]}); });
      double smax = 0;
      for (const auto &s : body.quadrature_stresses(u))
        smax = std::max({smax, std::abs(s.sxx), std::abs(s.syy), std::abs(s.sxy)});
      EXPECT_LE(smax, 1e-6 * E * theta) << "Q" << p;
      const auto tip = body.displacement_at(u, Point<2>(0.0, 0.02));
      EXPECT_NEAR(tip[0], -theta * 0.02, 1e-12);
    }
}

// Bad input: p not in {1, 2}, nu >= 0.5, E <= 0 get named errors; no Dirichlet boundary
// is a solver error, not a NaN.
TEST(FemClosedForms, BadInput)
{
  const auto m = mesh::mesh_domain(mesh::annulus_domain(0.01, 0.02, 0.004));
  fem::FeOptions o;
  o.degree = 3;
  EXPECT_THROW(fem::ElasticBody(m, steel(), o), InputError);
  o.degree  = 1;
  auto bad  = steel();
  bad.poisson_ratio = 0.5;
  EXPECT_THROW(fem::ElasticBody(m, bad, o), InputError);
  bad                = steel();
  bad.youngs_modulus = 0;
  EXPECT_THROW(fem::ElasticBody(m, bad, o), InputError);
  fem::ElasticBody body(m, steel(), o);
  EXPECT_THROW(body.assemble_and_factorize(), SolverError);
}

// Reference: full solves K u = e_d on the same factors, and Maxwell-Betti reciprocity
// (C = K^{-1} is symmetric). The flexibility columns of the contact come from MUMPS's
// selected-entries solve on its LDL^T factors of the SPD stiffness; they must equal the
// corresponding entries of full solves (to 1e-10) and C(i, j) = C(j, i).
TEST(FemClosedForms, SelectedEntriesOfTheInverseEqualFullSolves)
{
  const auto m = mesh::mesh_domain(mesh::annulus_domain(0.01, 0.02, 0.003));
  fem::FeOptions o;
  o.degree = 2;
  o.solver = fem::SolverKind::mumps;
  fem::ElasticBody body(m, steel(), o);
  body.constrain(mesh::boundary::bore);
  body.assemble_and_factorize();
  ASSERT_EQ(body.solver_used(), fem::SolverKind::mumps);
  const unsigned int n = body.n_dofs();
  // Columns spread over the body, each with its own rows (the other columns' DoFs and a few
  // more), as the contact requests them.
  const std::vector<unsigned int> cols = {n - 1, n / 2, n / 3 + 1, 7};
  std::vector<std::vector<unsigned int>> rows(cols.size());
  for (std::size_t j = 0; j < cols.size(); ++j)
    {
      rows[j] = cols;
      rows[j].push_back((cols[j] + 11) % n);
      rows[j].push_back((cols[j] + n / 5) % n);
    }
  const auto C = body.compliance_columns(cols, rows);
  double scale = 0;
  for (std::size_t j = 0; j < cols.size(); ++j)
    {
      dealii::Vector<double> e(n);
      e[cols[j]]   = 1.0;
      const auto u = body.solve(e);
      scale        = std::max(scale, u.linfty_norm());
      ASSERT_EQ(C[j].size(), rows[j].size());
      for (std::size_t i = 0; i < rows[j].size(); ++i)
        EXPECT_NEAR(C[j][i], u[rows[j][i]], 1e-10 * u.linfty_norm()) << "column " << cols[j] << ", row " << rows[j][i];
    }
  ASSERT_GT(scale, 0);
  for (std::size_t j = 0; j < cols.size(); ++j)
    for (std::size_t k = 0; k < cols.size(); ++k)
      EXPECT_NEAR(C[j][k], C[k][j], 1e-10 * scale);
}
