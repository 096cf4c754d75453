#ifndef tribos_core_bulk_assembler_h
#define tribos_core_bulk_assembler_h

#include <tribos/core/dynamics_state.h>
#include <tribos/core/kinematics.h>
#include <tribos/core/material_state.h>
#include <tribos/parameters/all_parameters.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <map>
#include <memory>

namespace tribos
{
  using namespace dealii;

  /**
   * The bulk of the bodies: their internal forces and tangent (each cell's
   * material through its Kinematics), the applied loads (Neumann tractions
   * on boundary faces, the body force), the stabilization springs and, in
   * dynamics, the inertia (DynamicsState::add_inertia()). Cells are
   * assembled in parallel over the threads (WorkStream); the copier adds
   * them in cell order, so the sums are those of a serial loop, bit for
   * bit.
   */
  template <int dim>
  class BulkAssembler
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    /** Where an assembly writes: the system (if with a matrix) and the
     * force vectors (null: not wanted). */
    struct Targets
    {
      TrilinosWrappers::SparseMatrix *matrix = nullptr;
      Vector                         *rhs    = nullptr;
      /** -R with the homogeneous constraints. */
      Vector *free_residual = nullptr;
      /** R = f_int - f_ext, unconstrained (in dynamics the static forces
       * alone). */
      Vector *full_residual = nullptr;
      /** The stabilization springs' forces, the applied forces alone, and
       * M a_{n+1} (dynamics). */
      Vector *stabilization = nullptr;
      Vector *external      = nullptr;
      Vector *inertia       = nullptr;
    };

    /**
     * The loads of Boundary conditions (Neumann, Body force) and the
     * @p kinematics' variant for @p fe with @p quadrature on the cells
     * @p owned_cells (this process's, in the order of its sums; their
     * reference geometry @p mapping), whose materials
     * and history are @p materials.
     */
    BulkAssembler(
      const Parameters::AllParameters &parameters,
      const std::vector<typename DoFHandler<dim>::active_cell_iterator>
                                &owned_cells,
      const Mapping<dim>        &mapping,
      const FESystem<dim>       &fe,
      const Quadrature<dim>     &quadrature,
      const Quadrature<dim - 1> &face_quadrature,
      MaterialState<dim>        &materials,
      const MPI_Comm             mpi_communicator);

    /**
     * Assemble at the displacement @p u (ghosted) and @p time into
     * @p targets: the matrix and right-hand side with @p constraints (if
     * targets.matrix), the free residual with @p homogeneous. With
     * stabilization (Nonlinear solver/Stabilization) the springs pull the
     * unknowns @p solution towards @p anchors (both ghosted); @p dynamics
     * (if not null and with inertia) adds the inertia. Throws
     * InvertedElement on every process if a cell is inverted on one.
     */
    void
    assemble(const Vector                    &u,
             const Vector                    &solution,
             const Vector                    &anchors,
             const double                     time,
             const AffineConstraints<double> &constraints,
             const AffineConstraints<double> &homogeneous,
             const DynamicsState<dim>        *dynamics,
             const Targets                   &targets);

    /** What @p f gets at every quadrature point of the own cells: the
     * cell's kinematics (its FEValues, the point's weight), the point and
     * what the material sees there. */
    using PointFunction = std::function<
      void(const typename DoFHandler<dim>::active_cell_iterator &cell,
           const Kinematics<dim>                                &kinematics,
           const unsigned int                                    q,
           const MaterialPoint<dim>                             &point)>;

    /** Call @p f at every quadrature point of every own cell at the
     * displacement @p u (the converged state's outputs). */
    void
    for_each_material_point(const Vector &u, const PointFunction &f) const;

    /** The stored strain energy of the converged history at @p u
     * (collective). */
    double
    stored_energy(const Vector &u) const;

    /** Seconds this process spent in its own cells (the load balance). */
    double
    own_time() const
    {
      return own_seconds;
    }

  private:
    const Parameters::AllParameters &parameters;
    /** This process's cells, in the order the sums take
     * (Model::owned_cells()). */
    const std::vector<typename DoFHandler<dim>::active_cell_iterator>
                              &owned_cells;
    const FESystem<dim>       &fe;
    const Quadrature<dim>     &quadrature;
    const Quadrature<dim - 1> &face_quadrature;
    MaterialState<dim>        &materials;
    MPI_Comm                   mpi_communicator;
    /** The kinematics every thread clones. */
    std::unique_ptr<Kinematics<dim>> kinematics;
    std::map<types::boundary_id, std::unique_ptr<FunctionParser<dim>>>
                                         neumann_functions;
    std::unique_ptr<FunctionParser<dim>> body_force;
    double                               own_seconds = 0;
  };
} // namespace tribos

#endif
