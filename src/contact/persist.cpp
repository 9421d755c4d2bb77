// The contact set's state between increments, for checkpoints: written and
// read by the same lines, so a member added here is restored as it is saved.
#include "tubeform/contact/contact.hpp"

namespace tf {

PetscErrorCode ContactSet::Persist(Archive &ar)
{
  PetscFunctionBeginUser;
  ar.Group("/contact");
  PetscCall(ar.Value("removed", removed_));
  PetscCall(ar.Value("dies_removed", dies_removed_));
  PetscCall(ar.Value("predict", predict_));
  PetscCall(ar.Value("settled", settled_));
  PetscCall(ar.Value("f_small", f_small_));
  PetscCall(ar.Value("pad_step", pad_step_));
  std::vector<double> strokes;
  for (const Tool &t : tools_) strokes.push_back(t.stroke);
  PetscCall(ar.Values("strokes", strokes));
  PetscCheck(strokes.size() == tools_.size(), comm(), PETSC_ERR_USER_INPUT,
             "%s: /contact/strokes has %zu tools, this run has %zu (the same options as the run that wrote it?)",
             ar.path().c_str(), strokes.size(), tools_.size());
  for (size_t k = 0; k < tools_.size(); ++k) tools_[k].stroke = strokes[k];
  for (auto [name, v] : {std::pair{"contact", &contact_},
                         {"global_frame", &global_frame_},
                         {"released", &released_},
                         {"frozen", &frozen_}})
    PetscCall(ar.Nodes(name, *v));
  PetscCall(ar.Nodes("segment", segment_));
  PetscCall(ar.Nodes("tool", tool_of_));
  PetscCall(ar.Nodes("touch", touch_));
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
