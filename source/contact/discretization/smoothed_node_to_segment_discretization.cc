#include <tribos/contact/contact_pair.h>
#include <tribos/contact/discretization/smoothed_node_to_segment_discretization.h>
#include <tribos/contact/surface/smoothed_segment.h>

#include <cmath>
#include <limits>

namespace tribos
{
  void
  SmoothedNodeToSegmentDiscretization::stencil_of(
    const ContactPair<2>            &pair,
    const unsigned int               face,
    const std::vector<Vec3<double>> &positions,
    Vec3<double>                    *x,
    bool                            *has)
  {
    const auto &f = pair.master->faces()[face];
    x[0]          = positions[f.nodes[0]];
    x[1]          = positions[f.nodes[1]];
    for (unsigned int side = 0; side < 2; ++side)
    {
      has[side]   = f.beyond[side] >= 0;
      x[2 + side] = has[side] ? positions[f.beyond[side]] : x[side];
    }
  }



  bool
  SmoothedNodeToSegmentDiscretization::pair_node(ContactPair<2>    &pair,
                                                 const unsigned int k)
  {
    NodeState          &state = pair.current[k];
    const Vec3<double> &x     = pair.slave_positions[k];
    const auto         &faces = pair.master->faces();

    // The smoothed projection onto one face: inside, or on the extension
    // beyond a free end of the master within the edge band.
    const auto try_face = [&](const unsigned int f, Projection &p) -> int
    {
      Vec3<double> xm[4];
      bool         has[2];
      stencil_of(pair, f, pair.master_positions, xm, has);
      double xi;
      if (!SmoothedSegment::project(x, xm, has, xi))
        return 0;
      const double xbar[2] = {0.5 * (1 - xi) * xm[0][0] +
                                0.5 * (1 + xi) * xm[1][0],
                              0.5 * (1 - xi) * xm[0][1] +
                                0.5 * (1 + xi) * xm[1][1]};
      p                    = Projection();
      p.xi[0]              = xi;
      p.distance           = std::hypot(x[0] - xbar[0], x[1] - xbar[1]);
      if (std::abs(xi) <= 1.)
        return 2;
      const int side = xi > 0 ? 1 : 0;
      p.clamped[0]   = xi > 0 ? 1 : -1;
      if (!faces[f].continues[0][side] && std::abs(xi) <= 1. + edge_band)
        return 1;
      return 0;
    };

    // The face of the last evaluation while the node still projects onto
    // it: the projection is continuous across vertices, so this only saves
    // the search.
    if (state.paired && pair.face_known[state.face])
    {
      Projection p;
      const int  kind = try_face(state.face, p);
      if (kind > 0 && p.distance <= parameters.search_distance)
      {
        state.projection = p;
        return couple_face(pair, k);
      }
    }
    state.paired         = false;
    state.face           = -1;
    state.distance       = std::numeric_limits<double>::quiet_NaN();
    int    best_kind     = 0;
    double best_distance = std::numeric_limits<double>::max();
    for (const unsigned int f : candidate_faces(pair, x, state))
    {
      Projection p;
      const int  kind = try_face(f, p);
      if (kind > best_kind ||
          (kind == best_kind && kind > 0 && p.distance < best_distance))
      {
        best_kind        = kind;
        best_distance    = p.distance;
        state.face       = f;
        state.projection = p;
      }
    }
    state.paired = best_kind > 0;
    return couple_face(pair, k);
  }



  void
  SmoothedNodeToSegmentDiscretization::element_dofs(
    const ContactPair<2>                 &pair,
    const unsigned int                    k,
    const int                             face,
    std::vector<types::global_dof_index> &dofs) const
  {
    const auto &slave_dofs = pair.slave->nodes()[k].dofs;
    dofs.assign(slave_dofs.begin(), slave_dofs.end());
    if (face >= 0)
    {
      const auto &f = pair.master->faces()[face];
      for (unsigned int i = 0; i < f.n_nodes(); ++i)
        for (const auto dof : pair.master->nodes()[f.node(i)].dofs)
          dofs.push_back(dof);
      for (const int m : f.beyond)
        if (m >= 0)
          for (const auto dof : pair.master->nodes()[m].dofs)
            dofs.push_back(dof);
    }
    pair.append_unknown_dofs(k, dofs);
  }



  ElementOutcome
  SmoothedNodeToSegmentDiscretization::evaluate(
    ContactPair<2>                       &pair,
    const unsigned int                    k,
    const SlaveInput                     &slave,
    double                               *R,
    double                               *K,
    std::vector<types::global_dof_index> &dofs,
    std::string &)
  {
    NodeState    &state = pair.current[k];
    const int     face  = state.face;
    SmoothedInput segment;
    bool          has_old[2];
    Vec3<double>  x_old[4];
    stencil_of(pair, face, pair.master_positions, segment.x, segment.has);
    stencil_of(pair, face, pair.old_master_positions, x_old, has_old);
    segment.x_old[0] = x_old[0];
    segment.x_old[1] = x_old[1];
    segment.xi       = state.projection.xi[0];
    state.result =
      NodeToSmoothedSegment::evaluate(slave, segment, *pair.enforcement, R, K);
    state.point = slave.position - scale(state.result.gap, state.result.normal);
    element_dofs(pair, k, face, dofs);
    return {ElementOutcome::Kind::element, true};
  }
} // namespace tribos
