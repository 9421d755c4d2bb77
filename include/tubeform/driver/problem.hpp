// A run (METHOD.md section 4): the distributed mesh, the body, the global
// system, the contact set and inertia when the scene needs them, and the
// incremental loop that drives them along the scene's load path.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "tubeform/assembly/system.hpp"
#include "tubeform/body/body.hpp"
#include "tubeform/body/inertia.hpp"
#include "tubeform/contact/contact.hpp"
#include "tubeform/driver/controller.hpp"
#include "tubeform/io/history.hpp"
#include "tubeform/io/options.hpp"
#include "tubeform/io/output.hpp"
#include "tubeform/mesh/mesh.hpp"
#include "tubeform/metrics/energy.hpp"
#include "tubeform/scenes/scene.hpp"

namespace tf {

class Problem {
public:
  Problem() = default;
  Problem(const Problem &) = delete;
  Problem &operator=(const Problem &) = delete;
  ~Problem();

  // Collective: the scene of -scene (or one made by the caller, for tests),
  // its mesh partitioned and distributed, the body, system, inertia, contact.
  PetscErrorCode Setup(MPI_Comm comm, const Options &opt);
  PetscErrorCode Setup(MPI_Comm comm, const Options &opt, std::unique_ptr<Scene> scene);
  // Collective: the load path from lambda = 0 to its end; results written.
  PetscErrorCode Run();

  MPI_Comm comm() const { return comm_; }
  Mesh &mesh() { return mesh_; }
  const Body &body() const { return body_; }
  const History &history() const { return history_; }

private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  PetscMPIInt rank_ = 0, size_ = 1;
  Options opt_;
  std::unique_ptr<Scene> scene_;
  LoadPath path_;
  Mesh mesh_;
  System system_;
  Body body_;
  std::unique_ptr<Inertia> inertia_;    // -dynamics implicit or auto
  std::unique_ptr<ContactSet> contact_; // scenes with tools
  std::unique_ptr<Model> model_;        // what the scene sees
  History history_;

  // The state of the loop between increments.
  struct Forces {
    Vec f_ext = nullptr, f_int = nullptr;   // at the end of the last increment (local contribution vectors)
    Vec f_ext0 = nullptr, f_int0 = nullptr; // at its start
    Vec f_res = nullptr;                    // out-of-balance force f_ext - f_int
  } forces_;
  EnergyAccount energy_;
  PetscInt unsettled_ = 0; // trial steps taken unsettled, so far
  bool warned_ = false;    // the energy warning was printed

  PetscErrorCode CreateForces(Vec like);
  PetscErrorCode DestroyForces();
  // Step 4 of Run: the increment's forces, energies and the scene's measurements into the history.
  PetscErrorCode Record(PetscInt inc, double lambda, const Increment &step, const Body::CommitInfo &ci,
                        double dw_friction, double dw_inertia, Vec du);
  PetscErrorCode PrintMonitor(PetscInt inc, double lambda, const Increment &step, const HistoryRow &row);
  PetscErrorCode WriteFields(ResultWriter &writer, PetscInt step, double t);
};

} // namespace tf
