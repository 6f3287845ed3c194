// The sections a solve request reads (route/route.h).
#include "route/route.h"

#include "deviations/parameters.h"
#include "model_choice/parameters.h"
#include "post/parameters.h"

#include <deal.II/base/parameter_handler.h>

namespace gearfem::route
{
  void declare_request(dealii::ParameterHandler &prm)
  {
    solve::declare_gear_contact_input(prm);
    post::declare_post_parameters(prm);
    deviations::declare_deviation_parameters(prm);
  }

  Request parse_request(dealii::ParameterHandler &prm)
  {
    Request r;
    r.input = solve::parse_gear_contact_input(prm);
    r.post  = post::parse_post_parameters(prm);
    r.dev   = deviations::parse_deviation_parameters(prm);
    r.fixed = model_choice::fixed_settings(prm);
    return r;
  }
} // namespace gearfem::route
