#ifndef tribos_core_material_state_h
#define tribos_core_material_state_h

#include <tribos/material/material.h>
#include <tribos/parameters/all_parameters.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /**
   * The deformation gradient a material sees at a quadrature point: F, or
   * in an axisymmetric model F3 (3 x 3, with the hoop stretch 1 + u_r / r;
   * F is then its in-plane part). F-bar scales it to the volume change of
   * the cell centre.
   */
  template <int dim>
  struct MaterialPoint
  {
    Tensor<2, dim> F;
    Tensor<2, 3>   F3;
    /** F3 is the one the material sees. */
    bool axisymmetric = false;
  };



  /**
   * The materials of a scene and their state at the quadrature points: one
   * Material per body (material id), in an axisymmetric model also its 3D
   * version (evaluated at the deformation gradient with the hoop stretch),
   * and the history of the bodies whose material has memory, at every
   * quadrature point of the own cells, converged (old) and current (new).
   * Elastic bodies store nothing. The history is committed with a
   * converged increment and restored after a failed one.
   *
   * Only the bodies the mesh has get a material, found by their id: an id
   * is a name (a gmsh physical tag, an Abaqus set's id, up to 2^31 - 1),
   * not a size, and a table indexed by it took 5.5 GB for one body of
   * id 10^8.
   */
  template <int dim>
  class MaterialState
  {
  public:
    /**
     * The materials of Materials (per body id of @p triangulation, over
     * all processes) and the history storage of the own cells with
     * @p n_quadrature_points each. Checks an axisymmetric mesh for x >= 0.
     */
    MaterialState(const Parameters::AllParameters &parameters,
                  const Triangulation<dim>        &triangulation,
                  const unsigned int               n_quadrature_points,
                  const MPI_Comm                   mpi_communicator);

    /** The body ids of the whole mesh. */
    const std::set<types::material_id> &
    bodies() const
    {
      return body_ids;
    }

    /** The material of @p body (in-plane or 3D), a body of the mesh. */
    const Material<dim> &
    material(const types::material_id body) const
    {
      return *materials[index(body)];
    }

    /** Axisymmetric models: the 3D material of @p body. */
    const Material<3> &
    axisymmetric_material(const types::material_id body) const
    {
      return *axisymmetric_materials[index(body)];
    }

    double
    youngs_modulus(const types::material_id body) const
    {
      return material(body).youngs_modulus();
    }

    /** The Cauchy stress (3 x 3) at @p point of @p body with the converged
     * @p history (axisymmetric: zz is the hoop stress). */
    SymmetricTensor<2, 3>
    cauchy_stress(const types::material_id  body,
                  const MaterialPoint<dim> &point,
                  const double             *history) const
    {
      return point.axisymmetric ?
               axisymmetric_material(body).cauchy_stress(point.F3, history) :
               material(body).cauchy_stress(point.F, history);
    }

    /** The equivalent plastic strain of @p body with @p history. */
    double
    equivalent_plastic_strain(const types::material_id body,
                              const double            *history) const
    {
      return axisymmetric_materials.empty() ?
               material(body).equivalent_plastic_strain(history) :
               axisymmetric_material(body).equivalent_plastic_strain(history);
    }

    /** The stored energy per reference volume at @p point of @p body. */
    double
    stored_energy(const types::material_id  body,
                  const MaterialPoint<dim> &point,
                  const double             *history) const
    {
      return point.axisymmetric ?
               axisymmetric_material(body).stored_energy(point.F3, history) :
               material(body).stored_energy(point.F, history);
    }

    /** Whether some material has history (PEEQ is written). */
    bool
    any_history() const;

    /** History values per quadrature point of @p body. */
    unsigned int
    n_history_variables(const types::material_id body) const
    {
      return axisymmetric_materials.empty() ?
               material(body).n_history_variables() :
               axisymmetric_material(body).n_history_variables();
    }

    /** Whether @p cell (own, active) stores history. */
    template <class CellIterator>
    bool
    has_history(const CellIterator &cell) const
    {
      return history_offset[cell->active_cell_index()] !=
             numbers::invalid_unsigned_int;
    }

    /** The converged history at quadrature point @p q of @p cell (null if
     * its body has none). */
    template <class CellIterator>
    const double *
    old_history(const CellIterator &cell, const unsigned int q) const
    {
      const unsigned int n = n_history_variables(cell->material_id());
      return n > 0 ?
               &history_old[history_offset[cell->active_cell_index()] + q * n] :
               nullptr;
    }

    /** The current history at quadrature point @p q of @p cell (null if
     * its body has none). */
    template <class CellIterator>
    double *
    new_history(const CellIterator &cell, const unsigned int q)
    {
      const unsigned int n = n_history_variables(cell->material_id());
      return n > 0 ?
               &history_new[history_offset[cell->active_cell_index()] + q * n] :
               nullptr;
    }

    /** The converged history of @p cell, all its quadrature points (for a
     * checkpoint). */
    template <class CellIterator>
    std::vector<double>
    cell_history(const CellIterator &cell) const
    {
      const unsigned int n      = n_history_variables(cell->material_id());
      const auto         offset = history_offset[cell->active_cell_index()];
      return std::vector<double>(history_old.begin() + offset,
                                 history_old.begin() + offset + n * n_q_points);
    }

    /** Set the converged and current history of @p cell from
     * @p values (cell_history() of a checkpoint); false if they do not
     * fit. */
    template <class CellIterator>
    bool
    set_cell_history(const CellIterator        &cell,
                     const std::vector<double> &values)
    {
      const unsigned int n = n_history_variables(cell->material_id());
      if (values.size() != n * n_q_points)
        return false;
      std::copy(values.begin(),
                values.end(),
                history_old.begin() +
                  history_offset[cell->active_cell_index()]);
      return true;
    }

    /** The current history becomes the converged one. */
    void
    commit()
    {
      history_old = history_new;
    }

    /** Back to the converged history. */
    void
    restore()
    {
      history_new = history_old;
    }

  private:
    /** The position of @p body, a body of the mesh, in @p ids (and of
     * its material in @p materials). */
    unsigned int
    index(const types::material_id body) const
    {
      const auto it = std::lower_bound(ids.begin(), ids.end(), body);
      Assert(it != ids.end() && *it == body,
             ExcMessage("body " + std::to_string(body) +
                        " is not one of the mesh's"));
      return static_cast<unsigned int>(it - ids.begin());
    }

    std::set<types::material_id> body_ids;
    /** The same ids in ascending order, searched by index(). */
    std::vector<types::material_id> ids;
    /** The material of each body of @p ids, in their order. */
    std::vector<std::unique_ptr<Material<dim>>> materials;
    /** Axisymmetric models: the materials in 3D (empty otherwise). */
    std::vector<std::unique_ptr<Material<3>>> axisymmetric_materials;
    unsigned int                              n_q_points;
    /** Per active cell, the offset of its first quadrature point into the
     * flat arrays, or invalid for cells without history. */
    std::vector<unsigned int> history_offset;
    std::vector<double>       history_old;
    std::vector<double>       history_new;
  };
} // namespace tribos

#endif
