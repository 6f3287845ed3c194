// Stiffness components against independent closed forms in limit cases.
#include "analytical/compliance.h"
#include "base/units.h"
#include "analytical/elastic.h"
#include "analytical/quadrature.h"
#include "base/errors.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace gearfem::analytical;

namespace
{
  using gearfem::units::pi;
  const Material steel{210e9, 0.3};
} // namespace

TEST(Quadrature, PolynomialAndKink)
{
  // Exact: int_0^2 x^7 dx = 32; int_0^2 |x-1| dx = 1 (kink handled by a breakpoint).
  EXPECT_NEAR(integrate([](double x) { return std::pow(x, 7); }, 0, 2), 32.0, 1e-12);
  EXPECT_NEAR(integrate([](double x) { return std::abs(x - 1); }, 0, 2, 1e-12, 0, {1.0}), 1.0, 1e-14);
  // Endpoint singularity int_0^1 x^-1/2 = 2 (adaptive refinement).
  EXPECT_NEAR(integrate([](double x) { return 1 / std::sqrt(x); }, 0, 1, 1e-10), 2.0, 1e-6);
}

TEST(Hertz, LineContactClosedForm)
{
  // Johnson (1985) sec. 4.3: a = sqrt(4wR/(pi E*)), p0 = 2w/(pi a) = sqrt(w E*/(pi R)).
  const PlaneElastic s = plane_elastic(steel, PlaneCondition::plane_strain);
  const double w = 2.0e5, R1 = 0.02, R2 = 0.05;
  const HertzLineContact h = hertz_line_contact(w, R1, R2, s, s);
  const double R = R1 * R2 / (R1 + R2);
  const double Es = 1.0 / (2 * (1 - 0.09) / 210e9); // 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2
  EXPECT_NEAR(h.half_width, std::sqrt(4 * w * R / (pi * Es)), 1e-15);
  EXPECT_NEAR(h.peak_pressure / std::sqrt(w * Es / (pi * R)), 1.0, 1e-12);
  // Total load = integral of the elliptical pressure.
  const double W = integrate([&](double x) { return h.pressure(x); }, -h.half_width, h.half_width, 1e-10);
  EXPECT_NEAR(W / w, 1.0, 1e-6);
  // Plane stress (VALIDATION.md): p0 lower by sqrt(1 - nu^2) = 0.954, a larger by 1/0.954.
  const PlaneElastic ps = plane_elastic(steel, PlaneCondition::plane_stress);
  const HertzLineContact h2 = hertz_line_contact(w, R1, R2, ps, ps);
  EXPECT_NEAR(h2.peak_pressure / h.peak_pressure, std::sqrt(1 - 0.09), 1e-12);
  EXPECT_NEAR(h2.half_width / h.half_width, 1 / std::sqrt(1 - 0.09), 1e-12);
}

TEST(Hertz, WeberLogTermMatchesSeedFormula)
{
  // Gkimisis 2019 eq. 3.8 (plane strain, equal materials):
  // C_H = (2(1-nu^2)/pi)[ln(4 h1 h2/b_H^2) - nu/(1-nu)],
  // b_H^2 = 8 F (1-nu^2) CR1 CR2/(pi b E (CR1 + CR2)).
  const double E = 210e9, nu = 0.3, F = 5000, b = 0.02, CR1 = 0.012, CR2 = 0.03, h1 = 0.004,
               h2 = 0.0035;
  const double bH2 = 8 * F * (1 - nu * nu) * CR1 * CR2 / (pi * b * E * (CR1 + CR2));
  const double CH = 2 * (1 - nu * nu) / pi * (std::log(4 * h1 * h2 / bH2) - nu / (1 - nu));
  const PlaneElastic s = plane_elastic({E, nu}, PlaneCondition::plane_strain);
  const double a = hertz_line_contact(F / b, CR1, CR2, s, s).half_width;
  EXPECT_NEAR(a * a / bH2, 1.0, 1e-12);
  const double delta = weber_hertz_approach(F, b, a, h1, s) + weber_hertz_approach(F, b, a, h2, s);
  EXPECT_NEAR(E * b * delta / F / CH, 1.0, 1e-12);
  // Load dependence: C_H decreases by (2(1-nu^2)/pi) ln 2 when F doubles (b_H^2 ~ F).
  const double a2 = hertz_line_contact(2 * F / b, CR1, CR2, s, s).half_width;
  const double delta2 = weber_hertz_approach(2 * F, b, a2, h1, s) + weber_hertz_approach(2 * F, b, a2, h2, s);
  EXPECT_NEAR(E * b * (delta / F - delta2 / (2 * F)), 2 * (1 - nu * nu) / pi * std::log(2.0), 1e-10);
}

TEST(Hertz, PotentialEnergyConstant)
{
  // Yang & Lin (1987): k_h = pi E L/(4(1-nu^2)) for two equal plane-strain bodies.
  const PlaneElastic s = plane_elastic(steel, PlaneCondition::plane_strain);
  EXPECT_NEAR(hertz_stiffness_pe(s, s, 0.02) / (pi * 210e9 * 0.02 / (4 * (1 - 0.09))), 1.0, 1e-14);
}

TEST(Beam, UniformRectangularCantileverTimoshenko)
{
  // Uniform beam t, loaded at height d perpendicular to the axis (phi = 0, h = 0):
  // delta/F = d^3/(3 E I) + 1.2 d/(G A), I = b t^3/12, A = b t (Timoshenko).
  const double t = 0.006, d = 0.004, b = 0.02;
  ToothBeam beam;
  beam.thickness = [t](double) { return t; };
  beam.height = 0.005;
  ToothLoad load;
  load.y_contact = d;
  const PlaneElastic e = plane_elastic(steel, PlaneCondition::plane_stress);
  const BeamIntegrals I = beam_integrals(beam, load);
  EXPECT_NEAR(I.I1, d / t, 1e-12);
  EXPECT_NEAR(I.I2, d * d * d / (3 * t * t * t), 1e-12);
  const double ref = d * d * d / (3 * e.E * b * t * t * t / 12) + 1.2 * d / (e.G() * b * t);
  EXPECT_NEAR(beam_compliance(beam, load, b, e) / ref, 1.0, 1e-10);
  // The same with the thesis form 12 cos^2 phi [...]: 4 (d/t)^3 + 2.4(1+nu) d/t at phi = 0.
  EXPECT_NEAR(weber_beam_coefficient(I, 0.0, 0.3), 4 * std::pow(d / t, 3) + 2.4 * 1.3 * d / t, 1e-10);
}

TEST(Beam, InclinedLoadEqualsPotentialEnergyMomentForm)
{
  // Tian (2004): M = F cos(phi)(d - y) - F sin(phi) h. Weber moves the load along its line
  // to the axis: M = F cos(phi)(Psi - y), Psi = d - h tan(phi). Check the identity with a
  // direct quadrature of Tian's energy on a tapered tooth, and the axial/shear parts.
  const double t0 = 0.008, k = 0.6, b = 0.015;
  ToothBeam beam;
  beam.thickness = [=](double y) { return t0 - k * y; };
  beam.height = 0.009;
  ToothLoad load;
  load.y_contact = 0.0065;
  load.h = 0.5 * (t0 - k * load.y_contact);
  load.phi = 0.35;
  const PlaneElastic e = plane_elastic(steel, PlaneCondition::plane_stress);
  const double c = std::cos(load.phi), s = std::sin(load.phi);
  const double Ub = integrate(
    [&](double y) {
      const double M = c * (load.y_contact - y) - s * load.h;
      const double t = t0 - k * y;
      return M * M / (e.E * b * t * t * t / 12);
    },
    0, load.y_contact, 1e-12);
  const double Us = integrate([&](double y) { return 1.2 * c * c / (e.G() * b * (t0 - k * y)); }, 0,
                              load.y_contact, 1e-12);
  const double Ua = integrate([&](double y) { return s * s / (e.E * b * (t0 - k * y)); }, 0,
                              load.y_contact, 1e-12);
  const BeamParts p = beam_compliance_parts(beam, load, b, e);
  EXPECT_NEAR(p.bending / Ub, 1.0, 1e-9);
  EXPECT_NEAR(p.shear / Us, 1.0, 1e-9);
  EXPECT_NEAR(p.axial / Ua, 1.0, 1e-9);
  EXPECT_NEAR(beam_compliance(beam, load, b, e) / p.total(), 1.0, 1e-12);
}

TEST(Beam, LinearTaperClosedForm)
{
  // t = t0 - k y, Psi = d (phi = 0): I1 = ln(t0/u)/k, u = t0 - k d, and
  // I2 = [ln(t0/u) + 2u/t0 - 2 - u^2/(2 t0^2) + 1/2]/k^3 (substitution u = t0 - k y).
  const double t0 = 0.007, k = 0.5, d = 0.008;
  ToothBeam beam;
  beam.thickness = [=](double y) { return t0 - k * y; };
  beam.height = d;
  ToothLoad load;
  load.y_contact = d;
  const BeamIntegrals I = beam_integrals(beam, load);
  const double u = t0 - k * d;
  EXPECT_NEAR(I.I1 / (std::log(t0 / u) / k), 1.0, 1e-11);
  const double I2 = (std::log(t0 / u) + 2 * u / t0 - 2 - u * u / (2 * t0 * t0) + 0.5) / (k * k * k);
  EXPECT_NEAR(I.I2 / I2, 1.0, 1e-10);
}

TEST(Foundation, ODonnellConstantsAndPlaneConvention)
{
  // Cornell (1981) prints 16.67/pi = 50/(3 pi); Gkimisis 2019 has 50/(2 pi): the X^2 terms
  // differ by 3/2 exactly.
  const double X = 1.3, phi = 0.4, nu = 0.3;
  const double c2 = std::cos(phi) * std::cos(phi);
  const double common = (1 - nu * nu) * c2 * (2 * (1 - 2 * nu) / (1 - nu) * X +
                                              4.82 / pi * (1 + std::tan(phi) * std::tan(phi) / (2.4 * 1.3)));
  const double cc = odonnell_foundation_coefficient(X, phi, nu, ODonnellConstant::cornell_50_over_3pi);
  const double cs = odonnell_foundation_coefficient(X, phi, nu, ODonnellConstant::seed000_50_over_2pi);
  EXPECT_NEAR((cc - common) / ((1 - nu * nu) * c2 * X * X), 50.0 / 3 / pi, 1e-12);
  EXPECT_NEAR(50.0 / 3 / pi, 16.67 / pi, 2e-3); // Cornell's printed 16.67/pi
  EXPECT_NEAR((cs - common) / (cc - common), 1.5, 1e-12);
  // Plane strain: compliance = C_f/(E b) with the true E, nu (the thesis' definition).
  ToothBeam beam;
  beam.thickness = [](double) { return 0.006; };
  beam.height = 0.01;
  ToothLoad load;
  load.y_contact = 0.0078;
  load.h = 0.001;
  load.phi = phi;
  const double b = 0.02;
  const PlaneElastic pe = plane_elastic(steel, PlaneCondition::plane_strain);
  const double Xl = load.y_axis() / 0.006;
  EXPECT_NEAR(odonnell_foundation_compliance(beam, load, b, pe) * steel.E * b /
                odonnell_foundation_coefficient(Xl, phi, 0.3),
              1.0, 1e-12);
  // Plane stress is softer (the equivalent plane-strain body has E(1+2nu)/(1+nu)^2 < E).
  const PlaneElastic ps = plane_elastic(steel, PlaneCondition::plane_stress);
  EXPECT_GT(odonnell_foundation_compliance(beam, load, b, ps), odonnell_foundation_compliance(beam, load, b, pe));
}

TEST(Foundation, SainsotPolynomial)
{
  // The VALIDATION.md table (Sainsot, Velex & Duverger 2004) written out term by term at
  // h_fi = 2, theta_f = 0.2.
  const SainsotCoefficients k = sainsot_coefficients(2.0, 0.2);
  const double th = 0.2, h = 2.0;
  EXPECT_NEAR(k.L, -5.574e-5 / (th * th) - 1.9986e-3 * 4 - 2.3015e-4 * h / th + 4.7702e-3 / th + 0.0271 * h + 6.8045, 1e-12);
  EXPECT_NEAR(k.P, -50.952e-5 / (th * th) + 185.50e-3 * 4 + 0.0538e-4 * h / th + 53.300e-3 / th + 0.2895 * h + 0.9236, 1e-12);
  // Compliance with phi = 0 and u_f/S_f = X: (L X^2 + M X + P)/(E b).
  ToothBeam beam;
  const double Sf = 0.2 * 2 * 0.03; // S_f = 2 r_f theta_f
  beam.thickness = [=](double) { return Sf; };
  beam.height = 0.01;
  beam.root_radius = 0.03;
  beam.rim_inner_radius = 0.015;
  ToothLoad load;
  load.y_contact = 0.006;
  const PlaneElastic e = plane_elastic(steel, PlaneCondition::plane_stress);
  const double X = 0.006 / Sf;
  EXPECT_NEAR(sainsot_foundation_compliance(beam, load, 0.02, e) * e.E * 0.02, k.L * X * X + k.M * X + k.P, 1e-10);
  // A missing bore is an input error naming the parameter.
  beam.rim_inner_radius = 0;
  EXPECT_THROW(sainsot_foundation_compliance(beam, load, 0.02, e), gearfem::InputError);
}

TEST(Elastic, BadInput)
{
  EXPECT_THROW(plane_elastic({-1, 0.3}, PlaneCondition::plane_stress), gearfem::InputError);
  EXPECT_THROW(plane_elastic({2e11, 0.5}, PlaneCondition::plane_stress), gearfem::InputError);
  const PlaneElastic s = plane_elastic(steel, PlaneCondition::plane_stress);
  EXPECT_THROW(hertz_line_contact(-1, 0.01, 0.01, s, s), gearfem::InputError);
}
