// The contact set's state between increments, for checkpoints: written and
// read by the same lines, so a member added here is restored as it is saved.
#include "tubeform/contact/contact.hpp"

namespace tf {

PetscErrorCode ContactSet::Persist(Archive &ar)
{
  PetscFunctionBeginUser;
  ar.Group("/contact");
  PetscCall(ar.Value("removed", removed_));
  PetscCall(ar.Value("predict", predict_));
  PetscCall(ar.Value("settled", settled_));
  PetscCall(ar.Value("f_small", f_small_));
  PetscCall(ar.Value("stroke", tool_.stroke));
  for (auto [name, v] : {std::pair{"contact", &contact_},
                         {"global_frame", &global_frame_},
                         {"released", &released_},
                         {"frozen", &frozen_}})
    PetscCall(ar.Nodes(name, *v));
  PetscCall(ar.Nodes("segment", segment_));
  for (auto [name, v] : {std::pair{"fn", &fn_},
                         {"slip", &x_},
                         {"gap", &gap_},
                         {"kappa", &kappa_},
                         {"dxk", &dxk_},
                         {"fnk", &fnk_},
                         {"rate", &rate_},
                         {"last_dx", &last_dx_},
                         {"r4", &r4_},
                         {"r5", &r5_}})
    PetscCall(ar.Nodes(name, *v));
  PetscCall(ar.Nodes("n", n_));
  PetscCall(ar.Nodes("l", l_));
  // Pending forces are per-rank contributions: on the owned nodes only.
  PetscCall(ar.Nodes("pending", pending_, true));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
