#pragma once
// ParameterHandler binding of the `Finite elements` section (degree, solver, manifolds)
// and the conversion of the geometry module's Material into fem::Elasticity.
#include "fem/elastic_body.h"
#include "geometry/material.h"

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::fem
{
  /// Declare `Finite elements`: Degree, Linear solver, UMFPACK limit, Interior manifold.
  void declare_fe_parameters(dealii::ParameterHandler &prm);
  /// Read and validate `Finite elements` (InputError for p not in {1, 2}).
  FeOptions parse_fe_parameters(dealii::ParameterHandler &prm);
  /// E, nu of `m`, thickness = face width [m], plane stress unless `plane_strain`.
  Elasticity elasticity(const geometry::Material &m, double face_width, bool plane_strain);
} // namespace gearfem::fem
