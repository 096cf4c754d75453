#include <tribos/base/exceptions.h>
#include <tribos/contact/contact_pair.h>
#include <tribos/contact/discretization/discretization_method.h>
#include <tribos/contact/discretization/node_to_segment_discretization.h>
#include <tribos/contact/discretization/rigid_surface_discretization.h>
#include <tribos/contact/discretization/self_contact_roles.h>
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
    own_neighbourhood.clear();
    if (pair.master != pair.slave)
      return;
    const auto &nodes = pair.slave->nodes();
    const auto &faces = pair.slave->faces();
    double      size  = 0;
    own_neighbourhood.resize(nodes.size());
    for (unsigned int k = 0; k < nodes.size(); ++k)
    {
      auto &near = own_neighbourhood[k];
      for (const unsigned int f : nodes[k].faces)
        for (unsigned int i = 0; i < faces[f].n_nodes(); ++i)
          for (const unsigned int g : nodes[faces[f].node(i)].faces)
            near.push_back(g);
      std::sort(near.begin(), near.end());
      near.erase(std::unique(near.begin(), near.end()), near.end());
      size = std::max(size, nodes[k].size);
    }
    // A surface whose every face is in every node's neighbourhood (two
    // segments, one quadrilateral) has nothing to touch.
    bool can_touch = false;
    for (const auto &near : own_neighbourhood)
      can_touch = can_touch || near.size() < faces.size();
    AssertThrow(can_touch,
                ExcMessage("Parameter <Contact/Pairs>: the self-contact pair "
                           "<" +
                           pair.description.text + "> has a surface of " +
                           std::to_string(faces.size()) +
                           " face(s), each of which shares a node with every "
                           "other: no node of it can touch a face of it that "
                           "is not its own or a neighbour of its own. A "
                           "self-contact surface needs faces apart from each "
                           "node's."));
    // The faces are looked for within twice the largest element size,
    // then twice as far until one is found or the reach passes twice the
    // way the node went in the increment (self_candidate_faces()), never
    // beyond twice the surface's extent or Search distance. A node that
    // an increment carries through an opposite face it had not touched
    // is then still within reach of it, and the face admissible (it was
    // in front of it at the start).
    double extent = 0;
    for (unsigned int d = 0; d < 3; ++d)
    {
      double lo = std::numeric_limits<double>::max(), hi = -lo;
      for (const auto &node : nodes)
      {
        lo = std::min(lo, node.reference[d]);
        hi = std::max(hi, node.reference[d]);
      }
      extent = std::max(extent, hi - lo);
    }
    reach         = 2 * size;
    maximum_reach = std::min(parameters.search_distance, 2 * extent);
    check_self_reach(pair);
  }



  template <int dim>
  void
  NodeToSegmentDiscretization<dim>::check_self_reach(
    const ContactPair<dim> &pair)
  {
    self_warning.clear();
    const double distance = parameters.search_distance;
    if (!std::isfinite(distance))
      return;
    const auto               &nodes = pair.slave->nodes();
    const auto               &faces = pair.slave->faces();
    std::vector<Vec3<double>> reference(nodes.size());
    for (unsigned int k = 0; k < nodes.size(); ++k)
      reference[k] = nodes[k].reference;
    // The faces' boxes, widened by the search distance.
    std::vector<std::array<double, 2 * dim>> boxes(faces.size());
    for (unsigned int f = 0; f < faces.size(); ++f)
      for (unsigned int d = 0; d < dim; ++d)
      {
        double lo = reference[faces[f].nodes[0]][d], hi = lo;
        for (unsigned int v = 1; v < faces[f].n_vertices; ++v)
        {
          lo = std::min(lo, reference[faces[f].nodes[v]][d]);
          hi = std::max(hi, reference[faces[f].nodes[v]][d]);
        }
        boxes[f][d]       = lo - distance;
        boxes[f][dim + d] = hi + distance;
      }
    // Does any node face a face of the surface, in front of it, within
    // the search distance (the reference configuration)?
    for (unsigned int k = 0; k < nodes.size(); ++k)
    {
      const Vec3<double> &x    = reference[k];
      const Vec3<double>  n_k  = node_normal(pair, k, &reference);
      const auto         &near = own_neighbourhood[k];
      for (unsigned int f = 0; f < faces.size(); ++f)
      {
        bool beyond = false;
        for (unsigned int d = 0; d < dim; ++d)
          beyond = beyond || x[d] < boxes[f][d] || x[d] > boxes[f][dim + d];
        if (beyond || std::binary_search(near.begin(), near.end(), f))
          continue;
        Vec3<double>     n_f, xbar;
        const Projection p = project(pair, f, x, true, &n_f, &xbar, &reference);
        if (p.distance <= distance && dot(n_k, n_f) < -0.5 &&
            dot(x - xbar, n_f) >= 0)
          return;
      }
    }
    self_warning = "the self-contact pair <" + pair.description.text +
                   ">: no node of its surface faces a face of it within "
                   "Contact/Search distance = " +
                   to_scientific(distance) +
                   " (the reference configuration); the surface touches "
                   "itself only where it folds closer than that.";
  }



  template <int dim>
  Projection
  NodeToSegmentDiscretization<dim>::project(
    const ContactPair<dim>          &pair,
    const unsigned int               f,
    const Vec3<double>              &x,
    const bool                       clamp,
    Vec3<double>                    *normal,
    Vec3<double>                    *point,
    const std::vector<Vec3<double>> *at) const
  {
    const auto  &face      = pair.master->faces()[f];
    const auto  &positions = at != nullptr ? *at : pair.master_positions;
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
  NodeToSegmentDiscretization<dim>::node_normal(
    const ContactPair<dim>          &pair,
    const unsigned int               k,
    const std::vector<Vec3<double>> *at) const
  {
    const auto  &positions = at != nullptr ? *at : pair.master_positions;
    Vec3<double> sum{{0, 0, 0}};
    for (const unsigned int f : pair.slave->nodes()[k].faces)
      if (at != nullptr || pair.face_known[f])
      {
        Vec3<double> n;
        project(pair, f, positions[k], true, &n, nullptr, at);
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
    const auto        &near = own_neighbourhood[k];
    const Vec3<double> n_k  = node_normal(pair, k);
    const double       size = pair.slave->nodes()[k].size;
    const auto         admissible =
      [&](const unsigned int f, double &distance, const double r)
    {
      if (!pair.face_known[f] ||
          std::binary_search(near.begin(), near.end(), f))
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
                &pair.old_master_positions);
        if (dot(pair.old_master_positions[k] - xbar_old, n_old) < -0.5 * size)
          return false;
      }
      distance = p.distance;
      return distance <= r;
    };
    // The farthest this node looks: the reach and twice the way it went
    // in this increment (the opposite side may have come as far).
    const double farthest =
      std::min(maximum_reach,
               reach + 2 * norm(x - pair.old_master_positions[k]));
    int    best          = -1;
    double best_distance = std::numeric_limits<double>::max();
    for (double r = std::min(reach, farthest); best < 0;)
    {
      for (const unsigned int f : pair.search.faces_near(x, r))
      {
        double distance;
        if (admissible(f, distance, r) && distance < best_distance)
        {
          best          = f;
          best_distance = distance;
        }
      }
      if (r >= farthest)
        break;
      r = std::min(2 * r, farthest);
    }
    if (best < 0)
      return {};
    state.distance = best_distance;
    std::vector<unsigned int> candidates(1, best);
    for (const unsigned int g : pair.master->faces()[best].neighbours)
    {
      double distance;
      if (admissible(g, distance, maximum_reach))
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
      const bool       self = !own_neighbourhood.empty();
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
      own_neighbourhood.empty() ? candidate_faces(pair, x, state) :
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
    if (!own_neighbourhood.empty() && !at_end && !state.projection.inside())
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
  void
  NodeToSegmentDiscretization<dim>::finish_pairing(ContactPair<dim> &pair,
                                                   const MPI_Comm communicator)
  {
    if (own_neighbourhood.empty() || pair.enforcement->n_node_unknowns() == 0)
      return;
    // Near: paired within two element sizes of its face, or behind it (a
    // node carried deep through the opposite side must have a role).
    std::vector<bool> near(pair.n_nodes(), false);
    for (unsigned int k = 0; k < pair.n_nodes(); ++k)
    {
      const NodeState &state = pair.current[k];
      if (!pair.owned[k] || !state.paired || state.face < 0)
        continue;
      Vec3<double> n, xbar;
      project(pair, state.face, pair.slave_positions[k], true, &n, &xbar);
      near[k] = state.projection.distance < 2 * pair.slave->nodes()[k].size ||
                dot(pair.slave_positions[k] - xbar, n) < 0;
    }
    assign_self_contact_roles(pair, near, communicator);
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

      template <int dim>
      std::unique_ptr<ContactDiscretization<dim>>
      make(const Parameters::ContactPair &pair,
           const Parameters::Contact     &parameters,
           const bool /*axisymmetric*/) const
      {
        if (!pair.rigid_surface.empty())
          return std::make_unique<RigidSurfaceDiscretization<dim>>(parameters);
        if (parameters.smoothing != Parameters::MasterSmoothing::none)
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
