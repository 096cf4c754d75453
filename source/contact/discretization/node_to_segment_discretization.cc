#include <tribos/base/exceptions.h>
#include <tribos/contact/contact_pair.h>
#include <tribos/contact/discretization/discretization_method.h>
#include <tribos/contact/discretization/node_to_segment_discretization.h>
#include <tribos/contact/discretization/rigid_surface_discretization.h>
#include <tribos/contact/discretization/smoothed_node_to_face_discretization.h>
#include <tribos/contact/discretization/smoothed_node_to_segment_discretization.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace tribos
{
  template <int dim>
  NodeToSegmentDiscretization<dim>::NodeToSegmentDiscretization(
    const Parameters::Contact &parameters)
    : parameters(parameters)
  {
  }



  template <int dim>
  void
  NodeToSegmentDiscretization<dim>::initialize(const ContactPair<dim> &pair)
  {
    require_linear_slave_faces(pair);
    self_search.initialize(pair, parameters.search_distance);
  }



  template <int dim>
  Projection
  NodeToSegmentDiscretization<dim>::project(const ContactPair<dim> &pair,
                                            const unsigned int      f,
                                            const Vec3<double>     &x,
                                            const bool              clamp,
                                            Vec3<double>           *normal,
                                            Vec3<double>           *point,
                                            const bool              old) const
  {
    const auto &face = pair.master->faces()[f];
    const auto &positions =
      old ? pair.old_master_positions : pair.master_positions;
    Vec3<double> xm[4];
    for (unsigned int v = 0; v < face.n_vertices; ++v)
      xm[v] = positions[face.nodes[v]];
    return pair.master->shape().template visit_linear<dim>(
      [&](auto kind)
      {
        const Projection p = decltype(kind)::project(x, xm, clamp);
        if (normal != nullptr || point != nullptr)
        {
          Vec3<double> xbar, a[2], n;
          decltype(kind)::geometry(xm, p.xi, xbar, a, n);
          if (normal != nullptr)
            *normal = n;
          if (point != nullptr)
            *point = xbar;
        }
        return p;
      });
  }



  template <int dim>
  Vec3<double>
  NodeToSegmentDiscretization<dim>::node_normal(const ContactPair<dim> &pair,
                                                const unsigned int      k) const
  {
    Vec3<double> sum{{0, 0, 0}};
    for (const unsigned int f : pair.slave->nodes()[k].faces)
      if (pair.face_known[f])
      {
        Vec3<double> n;
        project(pair, f, pair.master_positions[k], true, &n);
        sum = sum + n;
      }
    const double length = norm(sum);
    return length > 0 ? scale(1. / length, sum) : sum;
  }



  template <int dim>
  std::vector<unsigned int>
  NodeToSegmentDiscretization<dim>::self_candidate_faces(
    const ContactPair<dim> &pair,
    const unsigned int      k,
    const Vec3<double>     &x,
    NodeState              &state) const
  {
    const Vec3<double> n_k        = node_normal(pair, k);
    const double       size       = pair.slave->nodes()[k].size;
    const auto         admissible = [&](const unsigned int f, double &distance)
    {
      if (self_search.own(k, f))
        return false;
      Vec3<double>     n_f, xbar;
      const Projection p = project(pair, f, x, true, &n_f, &xbar);
      if (dot(n_k, n_f) > -0.5)
        return false;
      // Behind the face by more than half an element is the other side of
      // the node's own body, unless the node was not behind it at the
      // start of the increment: then it has gone through the face in this
      // increment (a first iterate carries nodes deep through an opposite
      // face they have not touched yet), a penetration.
      if (dot(x - xbar, n_f) < -0.5 * size)
      {
        Vec3<double> n_old, xbar_old;
        project(pair,
                f,
                pair.old_master_positions[k],
                true,
                &n_old,
                &xbar_old,
                true);
        if (dot(pair.old_master_positions[k] - xbar_old, n_old) < -0.5 * size)
          return false;
      }
      distance = p.distance;
      return true;
    };
    double    best_distance;
    const int best = self_search.closest(pair,
                                         k,
                                         x,
                                         norm(x - pair.old_master_positions[k]),
                                         admissible,
                                         best_distance);
    if (best < 0)
      return {};
    state.distance = best_distance;
    std::vector<unsigned int> candidates(1, best);
    for (const unsigned int g : pair.master->faces()[best].neighbours)
    {
      double distance;
      if (pair.face_known[g] && admissible(g, distance) &&
          distance <= self_search.maximum_reach())
        candidates.push_back(g);
    }
    return candidates;
  }



  template <int dim>
  bool
  NodeToSegmentDiscretization<dim>::couple_face(ContactPair<dim>  &pair,
                                                const unsigned int k)
  {
    const int face = pair.current[k].face;
    if (face < 0 || pair.couplings.count({k, face}) == 1)
      return false;
    ContactDiscretization<dim>::insert_couplings(pair, k, face, pair.couplings);
    return true;
  }



  template <int dim>
  bool
  NodeToSegmentDiscretization<dim>::pair_node(ContactPair<dim>  &pair,
                                              const unsigned int k)
  {
    NodeState          &state = pair.current[k];
    const Vec3<double> &x     = pair.slave_positions[k];
    const auto         &faces = pair.master->faces();
    const auto within_band    = [&](const unsigned int, const Projection &p)
    {
      return pair.master->shape().template visit_linear<dim>(
        [&](auto kind) { return decltype(kind)::within(p.xi, edge_band); });
    };

    // Keep the face of the last evaluation while the node projects onto it
    // or onto its extension within the edge band (see the class).
    // A face that is not known lies beyond the search distance.
    if (state.paired && pair.face_known[state.face])
    {
      const bool       self = self_search.active();
      Vec3<double>     n_f;
      const Projection kept =
        project(pair, state.face, x, false, self ? &n_f : nullptr);
      // Self-contact: kept while the face still faces the node.
      const bool facing = !self || dot(node_normal(pair, k), n_f) < 0;
      if (kept.distance <= parameters.search_distance && facing &&
          within_band(state.face, kept))
      {
        state.projection = kept;
        return couple_face(pair, k);
      }
    }
    state.paired   = false;
    state.face     = -1;
    state.distance = std::numeric_limits<double>::quiet_NaN();
    const std::vector<unsigned int> candidates =
      !self_search.active() ? candidate_faces(pair, x, state) :
                              self_candidate_faces(pair, k, x, state);
    if (candidates.empty())
      return false;

    // Exact projection on the candidate and its neighbours: prefer a
    // projection inside a face (the closest such), else the closest clamped
    // one.
    bool   best_inside   = false;
    double best_distance = std::numeric_limits<double>::max();
    for (const unsigned int f : candidates)
    {
      const Projection p      = project(pair, f, x, true);
      const bool       inside = p.inside();
      if ((inside && !best_inside) ||
          (inside == best_inside && p.distance < best_distance))
      {
        best_inside      = inside;
        best_distance    = p.distance;
        state.face       = f;
        state.projection = p;
      }
    }
    // A projection clamped at an edge where the master surface ends: within
    // a small band beyond the edge the node sees the face's extension (a
    // smooth residual for nodes flush with the end of the master); farther
    // out it has slid off: no contact.
    state.paired = true;
    bool at_end  = false;
    for (unsigned int c = 0; c < 3; ++c)
      if (state.projection.clamped[c] != 0 &&
          !faces[state.face].continues[c][state.projection.clamped[c] > 0])
        at_end = true;
    // Self-contact: the admissible faces are a part of the surface, which
    // ends where no admissible candidate continues the face (a neighbour
    // the node does not face, or that it is behind): a projection clamped
    // there is at an end too. (The U sheared with multipliers: an arm's
    // tip node above the other arm's tip took the face below the tip
    // face, clamped at their common vertex 0.33 away, and Newton cycled.)
    if (self_search.active() && !at_end && !state.projection.inside())
    {
      Vec3<double> corner;
      project(pair, state.face, x, true, nullptr, &corner);
      const double size = pair.slave->nodes()[k].size;
      at_end            = true;
      for (const unsigned int g : candidates)
        if (g != static_cast<unsigned int>(state.face) &&
            project(pair, g, corner, true).distance < 1e-9 * size)
          at_end = false;
    }
    if (at_end)
    {
      const Projection extended = project(pair, state.face, x, false);
      state.paired              = within_band(state.face, extended);
      state.projection          = extended;
    }
    return couple_face(pair, k);
  }



  template <int dim>
  std::vector<unsigned int>
  NodeToSegmentDiscretization<dim>::candidate_faces(
    const ContactPair<dim> &pair,
    const Vec3<double>     &x,
    NodeState              &state) const
  {
    unsigned int closest;
    double       squared_distance;
    if (!pair.search.closest_face(x, closest, squared_distance))
      return {};
    // Beyond the search distance the master is not looked for (the faces
    // there are not all known under MPI): no gap either.
    state.distance = std::sqrt(squared_distance);
    if (state.distance > parameters.search_distance)
    {
      state.distance = std::numeric_limits<double>::quiet_NaN();
      return {};
    }
    std::vector<unsigned int> candidates(1, closest);
    for (const unsigned int g : pair.master->faces()[closest].neighbours)
      if (pair.face_known[g])
        candidates.push_back(g);
    return candidates;
  }



  template <int dim>
  ElementOutcome
  NodeToSegmentDiscretization<dim>::evaluate(
    ContactPair<dim>                     &pair,
    const unsigned int                    k,
    const SlaveInput                     &slave,
    double                               *R,
    double                               *K,
    std::vector<types::global_dof_index> &dofs,
    std::string &)
  {
    NodeState     &state = pair.current[k];
    const int      face  = state.face;
    FaceInput<dim> input;
    const auto    &nodes = pair.master->faces()[face].nodes;
    input.shape          = pair.master->shape();
    for (unsigned int v = 0; v < pair.master->faces()[face].n_vertices; ++v)
    {
      input.x[v]     = pair.master_positions[nodes[v]];
      input.x_old[v] = pair.old_master_positions[nodes[v]];
    }
    input.projection = state.projection;
    input.same_face  = pair.committed[k].face == face;
    state.result =
      NodeToSegment<dim>::evaluate(slave, input, *pair.enforcement, R, K);
    state.point = slave.position - scale(state.result.gap, state.result.normal);
    this->element_dofs(pair, k, face, dofs);
    return {ElementOutcome::Kind::element, true};
  }



  template class NodeToSegmentDiscretization<2>;
  template class NodeToSegmentDiscretization<3>;



  namespace
  {
    /**
     * Contact/Discretization = node to segment, with its variants: a rigid
     * master is met node to rigid surface (every rigid pair is this
     * family's, whatever the default), Contact/Master smoothing = averaged
     * normals gives the smoothed master (segments in 2D, faces in 3D).
     */
    class NodeToSegmentMethod
      : public DiscretizationInBothDimensions<NodeToSegmentMethod>
    {
    public:
      bool
      handles_rigid_master() const override
      {
        return true;
      }

      /** The smoothed master removes the chattering between faces that
       * stalls Newton in large sliding (doc/robustness.md). */
      bool
      smooths_master_by_default(const unsigned int /*dim*/) const override
      {
        return true;
      }

      template <int dim>
      std::unique_ptr<ContactDiscretization<dim>>
      make(const Parameters::ContactPair &pair,
           const Parameters::Contact     &parameters,
           const bool /*axisymmetric*/) const
      {
        if (!pair.rigid_surface.empty())
          return std::make_unique<RigidSurfaceDiscretization<dim>>(parameters);
        if (pair.smoothing == Parameters::MasterSmoothing::averaged_normals)
        {
          if constexpr (dim == 2)
            return std::make_unique<SmoothedNodeToSegmentDiscretization>(
              parameters);
          else
            return std::make_unique<SmoothedNodeToFaceDiscretization>(
              parameters);
        }
        return std::make_unique<NodeToSegmentDiscretization<dim>>(parameters);
      }
    };

    // Rank 0: the first of Contact/Discretization's choices, and the
    // default of a pair without one.
    const DiscretizationRegistration node_to_segment_registration =
      register_discretization<NodeToSegmentMethod>(
        "node to segment",
        "each slave node is projected onto the master (the paper's)",
        0);
  } // namespace
} // namespace tribos
