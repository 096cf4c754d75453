#include <tribos/base/exceptions.h>
#include <tribos/contact/element/mortar_integrals.h>
#include <tribos/contact/surface/smoothed_segment.h>

#include <algorithm>
#include <cmath>

namespace tribos
{
  namespace internal
  {
    template <int dim>
    ContactPointResult
    finish_mortar(const SlaveInput       &slave,
                  const Enforcement<dim> &enforcement,
                  MortarIntegrals<dim>   &integrals,
                  double                 *R,
                  double                 *K,
                  bool                   &paired,
                  Vec3<double>           &weighted_point)
    {
      using AD                     = ContactAD;
      const unsigned int  n_s      = integrals.n_s;
      const unsigned int  n_m      = integrals.n_m;
      const ContactAD    *D        = integrals.D;
      const ContactAD    *M        = integrals.M;
      const auto         *xs       = integrals.xs;
      const auto         *xm       = integrals.xm;
      const Vec3<double> *xs_old   = integrals.input->xs_old;
      const Vec3<double> *xm_old   = integrals.input->xm_old;
      Vec3<ContactAD>    &normal_j = integrals.normal_j;
      ContactPointResult  result;
      const AD            zero(0.);
      if (norm(normal_j).val() > 0)
        normal_j = scale(1. / norm(normal_j), normal_j);

      AD w = zero;
      for (unsigned int i = 0; i < n_s; ++i)
        w += D[i];
      paired = w.val() >= integrals.input->min_weight && w.val() > 0;
      if (!paired)
        return result;

      Vec3<AD> slave_point  = {{zero, zero, zero}};
      Vec3<AD> master_point = {{zero, zero, zero}};
      Vec3<AD> moved        = to<AD>(xs_old[0]);
      for (unsigned int i = 0; i < n_s; ++i)
      {
        slave_point = slave_point + scale(D[i] / w, xs[i]);
        moved       = moved - scale(D[i] / w, to<AD>(xs_old[i]));
      }
      for (unsigned int l = 0; l < n_m; ++l)
      {
        master_point = master_point + scale(M[l] / w, xm[l]);
        moved        = moved + scale(M[l] / w, to<AD>(xm_old[l]));
      }

      PointKinematics kinematics;
      kinematics.normal          = scale(-1., normal_j);
      kinematics.gap             = dot(master_point - slave_point, normal_j);
      const NodeState &committed = *slave.committed;
      kinematics.slip = slip_increment(moved, committed, kinematics.normal);
      kinematics.committed = committed_traction(committed, kinematics.normal);

      AD weights[MortarInput3D::max_slave_nodes + max_mortar_master_nodes_3d];
      // Both sides of a self-contact pair carry a share (area_factor).
      const double share = integrals.input->area_factor;
      for (unsigned int i = 0; i < n_s; ++i)
        weights[i] = share * D[i];
      for (unsigned int l = 0; l < n_m; ++l)
        weights[n_s + l] = -share * M[l];
      finish_weighted<dim>(kinematics,
                           weights,
                           n_s + n_m,
                           integrals.n_displacements,
                           share * w,
                           slave,
                           enforcement,
                           R,
                           K,
                           result);
      for (unsigned int d = 0; d < 3; ++d)
        weighted_point[d] =
          value_of(xs[0][d]) + master_point[d].val() - slave_point[d].val();
      return result;
    }

    template ContactPointResult
    finish_mortar<2>(const SlaveInput &,
                     const Enforcement<2> &,
                     MortarIntegrals<2> &,
                     double *,
                     double *,
                     bool &,
                     Vec3<double> &);
    template ContactPointResult
    finish_mortar<3>(const SlaveInput &,
                     const Enforcement<3> &,
                     MortarIntegrals<3> &,
                     double *,
                     double *,
                     bool &,
                     Vec3<double> &);
  } // namespace internal



  namespace
  {
    /**
     * The integrals of Mortar2D::evaluate() on straight segments (Q1):
     * D, M and the unnormalized normal_j from the seeded positions xs, xm
     * (as internal::integrate_quadratic() on Q2).
     */
    void
    integrate_linear(const MortarInput     &input,
                     const Vec3<ContactAD> *xs,
                     const Vec3<ContactAD> *xm,
                     ContactAD             *D,
                     ContactAD             *M,
                     Vec3<ContactAD>       &normal_j)
    {
      using AD = ContactAD;
      const Vec3<double> ez{{0., 0., 1.}};
      const Vec3<AD>     ez_ad = to<AD>(ez);
      const AD           zero(0.);

      struct Overlap
      {
        unsigned int m, c, d;
        AD           s_c, s_d, lo, hi;
      };
      // The nodal normal: the segments' unit normals (out of the slave body)
      // weighted by their share of w_j, so that a segment that leaves the
      // master (at a corner of the slave) fades out of it continuously.
      const double gauss = 1. / std::sqrt(3.);
      // The slave's normal, and with a smoothed master the master's.
      Vec3<AD> slave_normal = {{zero, zero, zero}};
      for (unsigned int s = 0; s < input.n_slave_segments; ++s)
      {
        const unsigned int a              = input.slave_segment[s][0],
                           b              = input.slave_segment[s][1];
        const Vec3<AD>     e              = xs[b] - xs[a];
        const AD           length_squared = dot(e, e);
        const AD           length         = sqrt(length_squared);
        const Vec3<double> n_s    = cross(ez, input.xs[b] - input.xs[a]);
        const bool         j_is_a = (a == 0);

        // The master segments facing this one, projected onto its line.
        Overlap      overlaps[max_mortar_master_nodes];
        unsigned int n_overlaps = 0;
        AD           covered    = zero;
        for (unsigned int m = 0; m < input.n_master_segments; ++m)
        {
          const unsigned int c   = input.master_segment[m][0],
                             d   = input.master_segment[m][1];
          const Vec3<double> n_m = cross(ez, input.xm[d] - input.xm[c]);
          if (dot(n_m, n_s) >= 0)
            continue;
          Overlap o;
          o.m   = m;
          o.c   = c;
          o.d   = d;
          o.s_c = dot(xm[c] - xs[a], e) / length_squared;
          o.s_d = dot(xm[d] - xs[a], e) / length_squared;
          if (std::abs(o.s_c.val() - o.s_d.val()) < 1e-12)
            continue;
          const AD &low  = o.s_c.val() < o.s_d.val() ? o.s_c : o.s_d;
          const AD &high = o.s_c.val() < o.s_d.val() ? o.s_d : o.s_c;
          o.lo           = low.val() > 0 ? low : zero;
          o.hi           = high.val() < 1 ? high : AD(1.);
          if (o.hi.val() <= o.lo.val())
            continue;
          covered += o.hi - o.lo;
          overlaps[n_overlaps++] = o;
        }
        // Dual where the master covers the segment, standard where it covers
        // half of it or less, blended in between.
        const AD   theta     = internal::dual_weight(input.dual, covered);
        const bool dual_here = theta.val() > 0;
        // The dual functions of the segment, Phi = A N with A = D_e M_e^-1
        // (M_e the segment's mass matrix, D_e its row sums) in the measure
        // of the integrals: 2 N_j - N_o on a plane; with the weight 2 pi r of
        // axisymmetry they differ, and the plane ones would give the node on
        // the axis a zero weight. c_j, c_o: the row of A of node j.
        AD c_j = 1., c_o = 0.;
        if (dual_here)
        {
          AD mass[2][2] = {{zero, zero}, {zero, zero}};
          for (const double g : {-gauss, gauss})
          {
            const AD t = 0.5 + 0.5 * g;
            AD       r = 1.;
            if (input.axisymmetric)
              r = xs[a][0] + t * (xs[b][0] - xs[a][0]);
            const AD N[2] = {j_is_a ? 1. - t : t, j_is_a ? t : 1. - t};
            for (unsigned int i = 0; i < 2; ++i)
              for (unsigned int k = 0; k < 2; ++k)
                mass[i][k] += 0.5 * r * N[i] * N[k];
          }
          // Row j of D_e M_e^-1 (index 0: node j, 1: the other node).
          const AD det = mass[0][0] * mass[1][1] - mass[0][1] * mass[1][0];
          const AD d_j = mass[0][0] + mass[0][1];
          c_j          = theta * d_j * mass[1][1] / det + (1. - theta);
          c_o          = -theta * d_j * mass[0][1] / det;
        }
        AD segment_weight = zero;

        for (unsigned int i = 0; i < n_overlaps; ++i)
        {
          const Overlap &o = overlaps[i];
          // A smoothed master: the averaged normals of the segment's ends.
          Vec3<AD> n_c, n_d;
          if (input.smoothed_master)
          {
            const int     *beyond = input.master_beyond[o.m];
            const Vec3<AD> x[4]   = {xm[o.c],
                                     xm[o.d],
                                     xm[beyond[0] >= 0 ? beyond[0] : o.c],
                                     xm[beyond[1] >= 0 ? beyond[1] : o.d]};
            const bool     has[2] = {beyond[0] >= 0, beyond[1] >= 0};
            SmoothedSegment::nodal_normals(x, has, n_c, n_d);
          }
          for (const double g : {-gauss, gauss})
          {
            const AD t      = 0.5 * (o.lo + o.hi) + 0.5 * (o.hi - o.lo) * g;
            AD       weight = 0.5 * (o.hi - o.lo) * length;
            if (input.axisymmetric)
              weight *= 2. * M_PI * (xs[a][0] + t * (xs[b][0] - xs[a][0]));
            const AD N_a   = 1. - t;
            const AD N_b   = t;
            const AD N_j   = j_is_a ? N_a : N_b;
            const AD N_o   = j_is_a ? N_b : N_a;
            const AD phi   = c_j * N_j + c_o * N_o;
            const AD eta   = (t - o.s_c) / (o.s_d - o.s_c);
            const AD w_phi = weight * phi;
            D[a] += w_phi * N_a;
            D[b] += w_phi * N_b;
            M[o.c] += w_phi * (1. - eta);
            M[o.d] += w_phi * eta;
            segment_weight += w_phi;
            // The master's smoothed normal, out of the master: minus.
            if (input.smoothed_master)
              normal_j =
                normal_j -
                scale(weight * N_j, scale(1. - eta, n_c) + scale(eta, n_d));
          }
        }
        slave_normal =
          slave_normal + scale(segment_weight / length, cross(ez_ad, e));
      }
      // The master's normal unless it points into the slave (averaged
      // normals at a sharp master corner the slave slides off can), where
      // the gap along it would change sign.
      if (!input.smoothed_master || dot(normal_j, slave_normal).val() <= 0)
        normal_j = slave_normal;
    }
  } // namespace



  ContactPointResult
  Mortar2D::evaluate(const SlaveInput     &slave,
                     const MortarInput    &input,
                     const Enforcement<2> &enforcement,
                     double               *R,
                     double               *K,
                     bool                 &paired,
                     Vec3<double>         &weighted_point)
  {
    MortarIntegrals<2> &integrals =
      MortarIntegrals<2>::for_element(input,
                                      enforcement.n_node_unknowns(),
                                      K != nullptr);
    input.shape.visit<2>(
      [&](auto kind)
      {
        if constexpr (std::is_same_v<decltype(kind), Segment3>)
          internal::integrate_quadratic(input,
                                        integrals.xs,
                                        integrals.xm,
                                        integrals.D,
                                        integrals.M,
                                        integrals.normal_j);
        else
          integrate_linear(input,
                           integrals.xs,
                           integrals.xm,
                           integrals.D,
                           integrals.M,
                           integrals.normal_j);
      });
    return internal::finish_mortar<2>(slave,
                                      enforcement,
                                      integrals,
                                      R,
                                      K,
                                      paired,
                                      weighted_point);
  }
} // namespace tribos
