#ifndef tribos_contact_contact_ad_h
#define tribos_contact_contact_ad_h

#include <tribos/contact/surface/vec3.h>

#include <Sacado.hpp>

namespace tribos
{
  /**
   * The forward AD number of the contact elements: at most 400
   * derivatives (3D node to segment: the slave and a bilinear face, 5
   * nodes x 3, plus the slave's 3 multipliers = 18; 2D mortar: up to 5
   * slave (Q2) and 24 master nodes x 2, plus 2 multipliers = 60; 3D mortar: up
   * to 13 slave and 36 master nodes x 3 on quadrilaterals, plus 3
   * multipliers = 150; on quadratic triangles up to 37 slave and 96
   * master nodes, 402: a six-node triangle has twice the nodes per area
   * of a four-node quadrilateral). Operations
   * and copies run over the derivatives in use only, so the capacity costs
   * the small elements nothing but stack. The element residual is written
   * once in this type and its derivative is the consistent tangent.
   */
  using ContactAD = Sacado::Fad::SLFad<double, 400>;

  /** The capacity of ContactAD: an element with more unknowns is refused
   * (a 3D mortar element whose node carries hanging nodes can reach it). */
  constexpr unsigned int max_contact_derivatives = 400;

  /** The most master nodes a 2D mortar element couples to one slave node
   * (Q2: a master up to about 3 times finer than the slave). */
  constexpr unsigned int max_mortar_master_nodes = 24;

  /** The most master nodes (and faces) a 3D mortar element couples to one
   * slave node: a 9 x 9 patch of master nodes over the 2 x 2 slave faces
   * around it, a bilinear master up to about 3 times finer than the
   * slave; quadratic triangles have about 4 times as many nodes per area
   * as bilinear quadrilaterals of the same size. */
  constexpr unsigned int max_mortar_master_nodes_3d = 96;

  /** The value of a number (AD or double). */
  inline double
  value_of(const ContactAD &x)
  {
    return x.val();
  }

  inline double
  value_of(const double x)
  {
    return x;
  }

  /** The value of a forward AD number of another capacity. */
  template <int n>
  double
  value_of(const Sacado::Fad::SLFad<double, n> &x)
  {
    return x.val();
  }

  /**
   * The kinematics of one contact point, functions of the element's
   * unknowns: the normal gap g_N (negative: penetration), the unit normal
   * n of the master, the slip increment dg_T of the step (tangential) and
   * the committed tangential traction turned with the surface (Q T_n).
   */
  struct PointKinematics
  {
    ContactAD       gap;
    Vec3<ContactAD> normal;
    Vec3<ContactAD> slip;
    Vec3<ContactAD> committed;
  };

  /** |v|, with a zero derivative at v = 0 (not the NaN of d sqrt at 0). */
  template <typename Number>
  Number
  safe_norm(const Vec3<Number> &v)
  {
    if (value_of(dot(v, v)) == 0)
      return Number(0.);
    return norm(v);
  }

  /** max(0, x) with the derivative of the branch taken. */
  template <typename Number>
  Number
  positive_part(const Number &x)
  {
    return value_of(x) > 0 ? x : Number(0.);
  }

  /**
   * The Coulomb return map (17)-(19), written once for every method: the
   * trial traction @p trial inside the cone of radius @p limit >= 0 is
   * kept (stick; equality to round-off, relative 1e-12, sticks as in the
   * paper's Table 1), outside it is brought back to the cone,
   * limit trial / |trial| (slip). Returns whether the point slips;
   * @p magnitude gets |trial|.
   *
   * A node that slipped at the last converged state starts an increment
   * on the cone and so sticks in the first iterate. Taking the slip branch
   * there instead (a "slip predictor", tried in issue 55) saved 12 % of
   * the primal penalty's iterations on the ironing, changed nothing with
   * multipliers or the mixed penalty, and broke the stick-slip cycles at
   * each reversal (12 cutbacks where there were none): Coulomb's slip does
   * not go on when the motion reverses, and only the iterate can tell.
   */
  template <typename Number>
  bool
  coulomb_return(const Vec3<Number> &trial,
                 const Number       &limit,
                 Vec3<Number>       &traction,
                 Number             &magnitude)
  {
    magnitude = safe_norm(trial);
    if (value_of(magnitude) > value_of(limit) * (1. + 1e-12))
    {
      traction = scale(limit / magnitude, trial);
      return true;
    }
    traction = trial;
    return false;
  }
} // namespace tribos

#endif
