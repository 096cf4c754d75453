#ifndef tribos_core_checkpoint_h
#define tribos_core_checkpoint_h

#include <tribos/solver/load_stepper.h>

#include <array>
#include <boost/serialization/array.hpp>
#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <map>
#include <string>
#include <vector>

namespace tribos
{
  /**
   * The converged state of a run after a nominal step, in a form that does
   * not depend on the number of MPI processes: dof vectors as the values
   * of each active cell's dofs in the triangulation's cell order, the
   * plastic history per cell, the contact state per slave node. A restart
   * rebuilds the mesh and dofs from the same parameter file (the mesh is
   * checked against the sizes stored here) and reads the state back, so
   * that the run goes on as the uninterrupted one would (to round-off).
   * Written with Boost.Serialization (binary archive) by rank 0.
   */
  struct Checkpoint
  {
    /** The layout version of this struct. 6: the increments rejected for
     * accuracy in the totals. 5: the contact couplings of the
     * sparsity pattern in the contact state, and the fingerprint holds
     * every entry of the parameters but those a restart may change (4:
     * the scene, the pairs and the materials only). */
    static constexpr unsigned int format = 6;

    unsigned int dimension      = 0;
    unsigned int n_active_cells = 0;
    unsigned int dofs_per_cell  = 0;
    unsigned int n_dofs         = 0;
    unsigned int n_multipliers  = 0;

    StepperState stepper;
    /** Stabilization::largest_ratio() (in the archive where the stepper's
     * totals kept it before format 4 had it there: the bytes are
     * unchanged). */
    double largest_stabilization_ratio = 0;

    /** Every active cell (CellId::to_binary), in CellId order: the same on
     * every partition of the mesh, shared or distributed. */
    std::vector<std::array<unsigned int, 4>> cells;
    /** Per dof vector (solution, velocity, ...): n_active_cells x
     * dofs_per_cell values, the cells in the order of @p cells. */
    std::map<std::string, std::vector<double>> cell_values;
    /** The contact multipliers (after the dofs in the solution). */
    std::vector<double> multipliers;
    /** Their change over the last increment (with cell_values["change"],
     * where stepper.change_increment > 0). */
    std::vector<double> multiplier_change;
    /** Per cell with history, in CellId order: the cell and its values. */
    std::vector<std::pair<std::array<unsigned int, 4>, std::vector<double>>>
      history;
    /** ContactHandler::committed_state(). */
    std::vector<char> contact;
    /** Scalars by name (dynamics' energies and times). */
    std::map<std::string, double> scalars;
    /** The VTU series written so far (time, file). */
    std::vector<std::pair<double, std::string>> pvd_records;
    /** What the state depends on beyond the sizes above, by name: the
     * entries of the parameters that define the model, as written, and
     * what the materials and pairs resolved to
     * (Checkpointer::fingerprint()). */
    std::map<std::string, std::string> fingerprint;
    /** Moments of the mesh's vertex coordinates (a moved or reshaped mesh
     * with the same cells and dofs changes them). */
    std::map<std::string, double> geometry;

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      StepperState  &s = stepper;
      StepperTotals &t = stepper.totals;

      archive &dimension &n_active_cells &dofs_per_cell &n_dofs &n_multipliers;
      archive &s.step &s.time &s.increment &s.converged_in_row;
      archive &s.change_increment &multiplier_change;
      archive &t.n_increments &t.n_newton_iterations &t.n_cutbacks;
      archive &largest_stabilization_ratio           &t.n_linear_solves;
      archive                                        &t.n_rejections;
      archive &cells &cell_values &multipliers &history &contact &scalars;
      archive &pvd_records &fingerprint                          &geometry;
    }

    /** Write to @p directory/state.bin (through a temporary file and a
     * rename of the directory, so that a checkpoint is whole or absent),
     * the archive behind a checksum of its bytes. */
    void
    save(const std::string &directory) const;

    /** Read from @p directory/state.bin; a clear error if it is missing,
     * not a checkpoint of this format, or changed since it was written
     * (the checksum). */
    void
    load(const std::string &directory);
  };
} // namespace tribos

#endif
