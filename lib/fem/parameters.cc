// The `Finite elements` section.
#include "fem/parameters.h"

#include "params/checked.h"

#include <deal.II/base/parameter_handler.h>

namespace gearfem::fem
{
  void declare_fe_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Finite elements");
    prm.declare_entry("Degree", "2", dealii::Patterns::Integer(),
                      "p of FE_Q(p)^2 and MappingQ(p). Units: none. Allowed: 1 or 2.",
                      true /* has_to_be_set: tells a set entry from a default (model_choice/parameters.h) */);
    prm.declare_entry("Linear solver", "automatic", dealii::Patterns::Selection("automatic|mumps|umfpack"),
                      "Direct solver: MUMPS through PETSc, UMFPACK, or automatic (UMFPACK up to "
                      "the UMFPACK limit, MUMPS above).");
    prm.declare_entry("UMFPACK limit", "20000", dealii::Patterns::Integer(0),
                      "Largest number of DoFs solved with UMFPACK when the solver is automatic. "
                      "Units: DoFs.");
    prm.declare_entry("Interior manifold", "none",
                      dealii::Patterns::Selection("boundary layer|all|none"),
                      "Cells with a transfinite-interpolation manifold: those touching a curved "
                      "boundary, all cells (best for high-order convergence studies), or none.");
    prm.leave_subsection();
  }

  FeOptions parse_fe_parameters(dealii::ParameterHandler &prm)
  {
    FeOptions o;
    prm.enter_subsection("Finite elements");
    const long p = params::get_integer(prm, "Degree");
    if (p != 1 && p != 2)
      throw InputError("Finite elements/Degree", std::to_string(p), "{1, 2}");
    o.degree           = unsigned(p);
    o.solver           = solver_kind_from_string(prm.get("Linear solver"));
    o.umfpack_max_dofs = params::get_integer(prm, "UMFPACK limit");
    const std::string im = prm.get("Interior manifold");
    o.interior = im == "all" ? mesh::InteriorManifold::all :
                 im == "none" ? mesh::InteriorManifold::none :
                                mesh::InteriorManifold::boundary_layer;
    prm.leave_subsection();
    o.validate();
    return o;
  }

  Elasticity elasticity(const geometry::Material &m, double face_width, bool plane_strain)
  {
    Elasticity e;
    e.youngs_modulus = m.youngs_modulus;
    e.poisson_ratio  = m.poisson_ratio;
    e.thickness      = face_width;
    e.model          = plane_strain ? PlaneModel::plane_strain : PlaneModel::plane_stress;
    return e;
  }
} // namespace gearfem::fem
