#include "analytical/compliance.h"
#include "base/units.h"

#include "analytical/quadrature.h"
#include "base/errors.h"

#include <cmath>

namespace gearfem::analytical
{
  namespace
  {
    using units::pi;

    void check(const ToothBeam &tooth, const ToothLoad &load)
    {
      if (!tooth.thickness)
        throw InputError("tooth beam: no thickness function t(y)");
      require_greater("tooth beam/height", tooth.height, 0.0, "m");
      if (!(load.y_contact > 0.0 && load.y_contact <= tooth.height * (1 + 1e-9)))
        throw InputError("tooth load/contact height", to_string_g(load.y_contact) + " m",
                         "(0, " + to_string_g(tooth.height) + "] m (between root and tip)");
      if (!(std::abs(load.phi) < 0.5 * pi))
        throw InputError("tooth load/load angle", to_string_g(load.phi) + " rad",
                         "(-pi/2, pi/2)");
    }
  } // namespace

  double ToothLoad::y_axis() const { return y_contact - h * std::tan(phi); }
  double ToothLoad::depth_to_axis() const { return h / std::cos(phi); }

  BeamIntegrals beam_integrals(const ToothBeam &tooth, const ToothLoad &load)
  {
    check(tooth, load);
    const double Psi = load.y_axis();
    const double d = std::min(load.y_contact, tooth.height);
    BeamIntegrals I;
    I.I1 = integrate([&](double y) { return 1.0 / tooth.thickness(y); }, 0.0, d, 1e-10, 0.0,
                     tooth.breakpoints);
    I.I2 = integrate(
      [&](double y) {
        const double t = tooth.thickness(y);
        return (y - Psi) * (y - Psi) / (t * t * t);
      },
      0.0, d, 1e-10, 0.0, tooth.breakpoints);
    return I;
  }

  double weber_beam_coefficient(const BeamIntegrals &I, double phi, double nu)
  {
    const double c2 = std::cos(phi) * std::cos(phi), t2 = std::tan(phi) * std::tan(phi);
    return 12.0 * c2 * (I.I2 + (0.2 * (1.0 + nu) + t2 / 12.0) * I.I1);
  }

  double beam_compliance(const ToothBeam &tooth, const ToothLoad &load, double b,
                         const PlaneElastic &mat)
  {
    require_greater("face width", b, 0.0, "m");
    return weber_beam_coefficient(beam_integrals(tooth, load), load.phi, mat.nu) / (mat.E * b);
  }

  BeamParts beam_compliance_parts(const ToothBeam &tooth, const ToothLoad &load, double b,
                                  const PlaneElastic &mat)
  {
    require_greater("face width", b, 0.0, "m");
    const BeamIntegrals I = beam_integrals(tooth, load);
    const double c = std::cos(load.phi), s = std::sin(load.phi);
    BeamParts p;
    // M = F cos(phi)(Psi - y): U = int M^2/(2 E I) dy with I = b t^3/12.
    p.bending = 12.0 * c * c * I.I2 / (mat.E * b);
    // Shear force F cos(phi), 1.2 form factor, area b t.
    p.shear = 1.2 * c * c * I.I1 / (mat.G() * b);
    // Axial force F sin(phi).
    p.axial = s * s * I.I1 / (mat.E * b);
    return p;
  }

  double odonnell_foundation_coefficient(double X, double phi, double nu, ODonnellConstant c)
  {
    const double k = c == ODonnellConstant::cornell_50_over_3pi ? 50.0 / (3.0 * pi) : 50.0 / (2.0 * pi);
    const double c2 = std::cos(phi) * std::cos(phi), t2 = std::tan(phi) * std::tan(phi);
    return (1.0 - nu * nu) * c2 *
           (k * X * X + 2.0 * (1.0 - 2.0 * nu) / (1.0 - nu) * X +
            4.82 / pi * (1.0 + t2 / (2.4 * (1.0 + nu))));
  }

  double odonnell_foundation_compliance(const ToothBeam &tooth, const ToothLoad &load, double b,
                                        const PlaneElastic &mat, ODonnellConstant c)
  {
    check(tooth, load);
    require_greater("face width", b, 0.0, "m");
    const double nu = mat.nu_plane_strain();
    const double X = load.y_axis() / tooth.thickness(0.0);
    // The plane-strain formula carries (1-nu^2)/E, which is 1/E' of the equivalent body.
    return odonnell_foundation_coefficient(X, load.phi, nu, c) / (1.0 - nu * nu) / (mat.E * b);
  }

  SainsotCoefficients sainsot_coefficients(double h, double th)
  {
    // Sainsot, Velex & Duverger (2004), table of VALIDATION.md.
    auto poly = [&](double A, double B, double C, double D, double E, double F) {
      return A / (th * th) + B * h * h + C * h / th + D / th + E * h + F;
    };
    return {poly(-5.574e-5, -1.9986e-3, -2.3015e-4, 4.7702e-3, 0.0271, 6.8045),
            poly(60.111e-5, 28.100e-3, -83.431e-4, -9.9256e-3, 0.1624, 0.9086),
            poly(-50.952e-5, 185.50e-3, 0.0538e-4, 53.300e-3, 0.2895, 0.9236),
            poly(-6.2042e-5, 9.0889e-3, -4.0964e-4, 7.8297e-3, -0.1472, 0.6904)};
  }

  double sainsot_foundation_compliance(const ToothBeam &tooth, const ToothLoad &load, double b,
                                       const PlaneElastic &mat)
  {
    check(tooth, load);
    require_greater("face width", b, 0.0, "m");
    require_greater("Gear/Bore radius (rim inner radius for the Sainsot foundation)",
                    tooth.rim_inner_radius, 0.0, "m");
    const double h_fi = tooth.root_radius / tooth.rim_inner_radius;
    require_range("Sainsot foundation/r_f/r_int", h_fi, 1.0, 10.0);
    const double Sf = tooth.thickness(0.0);
    const double theta_f = Sf / (2.0 * tooth.root_radius);
    const SainsotCoefficients k = sainsot_coefficients(h_fi, theta_f);
    const double u = load.y_axis() / Sf;
    const double c2 = std::cos(load.phi) * std::cos(load.phi);
    const double t2 = std::tan(load.phi) * std::tan(load.phi);
    return c2 / (mat.E * b) * (k.L * u * u + k.M * u + k.P * (1.0 + k.Q * t2));
  }
} // namespace gearfem::analytical
