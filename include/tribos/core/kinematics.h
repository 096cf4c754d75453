#ifndef tribos_core_kinematics_h
#define tribos_core_kinematics_h

#include <tribos/core/material_state.h>
#include <tribos/parameters/finite_element.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /** What Kinematics::add_point() evaluates at a point. */
  template <int dim>
  struct PointData
  {
    /** The materials; the point's body. */
    const MaterialState<dim> &materials;
    types::material_id        body;
    /** The converged history (read) and the current one (written); null
     * for a body without. */
    const double *old_history;
    double       *new_history;
    /** The body force at the point (null: none). */
    const dealii::Vector<double> *force;
  };



  /** A cell's terms that Kinematics::add_point() adds to. */
  struct CellTerms
  {
    /** -R; the tangent, if with_matrix (its upper triangle only if
     * upper_only); the applied forces alone, if not null. */
    dealii::Vector<double> &rhs;
    FullMatrix<double>     &matrix;
    dealii::Vector<double> *external;
    bool                    with_matrix;
    bool                    upper_only;
  };



  /**
   * The kinematics of the displacement field in a cell: the one place
   * that evaluates the deformation gradient at a quadrature point, for the
   * assembly (add_point(): the material's stress and tangent contracted
   * with the virtual deformation gradients of the cell's dofs) and for the
   * outputs of the converged state (material_point()). One object per
   * thread; it holds the cell's FEValues.
   *
   * The variants are the kinematic assumptions of Finite element/
   * (create_kinematics()): plane strain or 3D (StandardKinematics), with
   * F-bar for Q1 (FBarKinematics), axisymmetric (AxisymmetricKinematics),
   * axisymmetric with F-bar (AxisymmetricFBarKinematics).
   */
  template <int dim>
  class Kinematics
  {
  public:
    using CellIterator = typename DoFHandler<dim>::active_cell_iterator;
    using Vector       = TrilinosWrappers::MPI::Vector;

    /** On the cells of the reference geometry @p mapping (the mesh's
     * straight cells, or the curved ones of a second-order mesh). */
    Kinematics(const Mapping<dim>       &mapping,
               const FiniteElement<dim> &fe,
               const Quadrature<dim>    &quadrature);

    virtual ~Kinematics() = default;

    /** A copy for another thread. */
    virtual std::unique_ptr<Kinematics<dim>>
    clone() const = 0;

    /** Evaluate the displacement @p u (ghosted) on @p cell. */
    virtual void
    reinit(const CellIterator &cell, const Vector &u);

    /** The FEValues of the cell of the last reinit(). */
    const FEValues<dim> &
    values() const
    {
      return fe_values;
    }

    /** The weight of quadrature point @p q in a volume integral: JxW
     * (axisymmetric: times 2 pi r). */
    virtual double
    volume_weight(const unsigned int q) const
    {
      return fe_values.JxW(q);
    }

    /** The factor of a surface integral at the point @p x of a boundary
     * face: 1 (axisymmetric: 2 pi r). */
    virtual double
    ring(const Point<dim> & /*x*/) const
    {
      return 1.;
    }

    /** What the material sees at quadrature point @p q. */
    virtual MaterialPoint<dim>
    material_point(const unsigned int q) const = 0;

    /**
     * Whether a material with a symmetric tangent gives a symmetric cell
     * matrix (then only its upper triangle is computed by add_point()).
     */
    virtual bool
    keeps_symmetry() const
    {
      return false;
    }

    /**
     * Evaluate the material of @p point's body at quadrature point @p q
     * and add the point's share of -R (with the body force) and of the
     * tangent to @p cell's terms.
     */
    virtual void
    add_point(const unsigned int    q,
              const PointData<dim> &point,
              CellTerms            &cell) const = 0;

  protected:
    FEValues<dim> fe_values;
    /** The cell's dofs' components. */
    std::vector<unsigned int> component;
    /** The displacement gradient at the quadrature points. */
    std::vector<std::vector<Tensor<1, dim>>> gradients;
  };



  /** F = I + grad u (2D: plane strain, F_33 = 1). */
  template <int dim>
  class StandardKinematics : public Kinematics<dim>
  {
  public:
    using Kinematics<dim>::Kinematics;

    std::unique_ptr<Kinematics<dim>>
    clone() const override;

    MaterialPoint<dim>
    material_point(const unsigned int q) const override;

    bool
    keeps_symmetry() const override
    {
      return true;
    }

    void
    add_point(const unsigned int    q,
              const PointData<dim> &point,
              CellTerms            &cell) const override;

  protected:
    /** F = I + grad u at @p q. */
    Tensor<2, dim>
    deformation_gradient(const unsigned int q) const;

    /** Add P : grad(phi_i) JxW (minus the body force) to -R and, with
     * @p A, A's contraction with the dofs' gradients to the tangent. */
    void
    add_stress(const unsigned int            q,
               const Tensor<2, dim>         &P,
               const Tensor<4, dim>         *A,
               const dealii::Vector<double> *force,
               CellTerms                    &cell) const;
  };



  /**
   * F-bar (FBar): the material sees F scaled to the volume change of the
   * cell centre; the tangent couples every point with the centre.
   */
  template <int dim>
  class FBarKinematics : public StandardKinematics<dim>
  {
  public:
    FBarKinematics(const Mapping<dim>       &mapping,
                   const FiniteElement<dim> &fe,
                   const Quadrature<dim>    &quadrature);

    std::unique_ptr<Kinematics<dim>>
    clone() const override;

    void
    reinit(const typename Kinematics<dim>::CellIterator &cell,
           const typename Kinematics<dim>::Vector       &u) override;

    MaterialPoint<dim>
    material_point(const unsigned int q) const override;

    bool
    keeps_symmetry() const override
    {
      return false;
    }

    void
    add_point(const unsigned int    q,
              const PointData<dim> &point,
              CellTerms            &cell) const override;

  private:
    FEValues<dim>                            centre;
    std::vector<std::vector<Tensor<1, dim>>> centre_gradients;
    /** The centre's deformation gradient and volume change. */
    Tensor<2, dim> F0;
    double         J0 = 1;
  };



  /**
   * A 2D body of revolution (x = r, y = z): F3 = [[F_rr, F_rz, 0], [F_zr,
   * F_zz, 0], [0, 0, 1 + u_r / r]], the 3D material, and integrals over
   * the ring (weight 2 pi r). The virtual deformation gradient of a radial
   * dof has phi / r in its hoop entry.
   */
  class AxisymmetricKinematics : public Kinematics<2>
  {
  public:
    using Kinematics<2>::Kinematics;

    std::unique_ptr<Kinematics<2>>
    clone() const override;

    void
    reinit(const CellIterator &cell, const Vector &u) override;

    double
    volume_weight(const unsigned int q) const override;

    double
    ring(const Point<2> &x) const override
    {
      return 2. * numbers::PI * x[0];
    }

    MaterialPoint<2>
    material_point(const unsigned int q) const override;

    void
    add_point(const unsigned int  q,
              const PointData<2> &point,
              CellTerms          &cell) const override;

  protected:
    /** F3 at @p q (unscaled). */
    Tensor<2, 3>
    deformation_gradient(const unsigned int q) const;

    /** The hoop entry of dof @p i's virtual deformation gradient at @p q:
     * phi_i / r for a radial dof, else 0. */
    double
    hoop(const unsigned int i, const unsigned int q) const;

    /** As StandardKinematics::add_stress(), with the hoop terms and the
     * ring weight. */
    void
    add_stress(const unsigned int            q,
               const Tensor<2, 3>           &P3,
               const Tensor<4, 3>           *A3,
               const dealii::Vector<double> *force,
               CellTerms                    &cell) const;

    /** The radial displacement at the quadrature points. */
    std::vector<dealii::Vector<double>> values;
  };



  /** Axisymmetric with F-bar: the centre's volume change includes its
   * hoop stretch. */
  class AxisymmetricFBarKinematics : public AxisymmetricKinematics
  {
  public:
    AxisymmetricFBarKinematics(const Mapping<2>       &mapping,
                               const FiniteElement<2> &fe,
                               const Quadrature<2>    &quadrature);

    std::unique_ptr<Kinematics<2>>
    clone() const override;

    void
    reinit(const CellIterator &cell, const Vector &u) override;

    MaterialPoint<2>
    material_point(const unsigned int q) const override;

    void
    add_point(const unsigned int  q,
              const PointData<2> &point,
              CellTerms          &cell) const override;

  private:
    FEValues<2>                            centre;
    std::vector<std::vector<Tensor<1, 2>>> centre_gradients;
    std::vector<dealii::Vector<double>>    centre_values;
    /** The centre's F3, its volume change and radius. */
    Tensor<2, 3> F3_0;
    double       J0            = 1;
    double       centre_radius = 1;
  };



  /** The kinematics of @p parameters (Axisymmetric, F-bar) for @p fe with
   * @p quadrature on the cells of @p mapping. */
  template <int dim>
  std::unique_ptr<Kinematics<dim>>
  create_kinematics(const Parameters::FiniteElement &parameters,
                    const Mapping<dim>              &mapping,
                    const FiniteElement<dim>        &fe,
                    const Quadrature<dim>           &quadrature);
} // namespace tribos

#endif
