#include <tribos/contact/contact_pair.h>
#include <tribos/contact/discretization/smoothed_node_to_face_discretization.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tribos
{
  void
  SmoothedNodeToFaceDiscretization::initialize(const ContactPair<3> &pair)
  {
    NodeToSegmentDiscretization<3>::initialize(pair);
    faceted = false;
    fallback_warning.clear();
    const auto &faces = pair.master->faces();
    const auto &nodes = pair.master->nodes();
    AssertThrow(!pair.master->quadratic(),
                ExcMessage("Contact pair <" + pair.description.text +
                           ">: Contact/Master smoothing = averaged normals "
                           "works on the linear faces of Polynomial degree "
                           "= 1 (bilinear quadrilaterals, triangles)."));
    std::vector<std::vector<unsigned int>> face_vertices(faces.size());
    std::vector<std::vector<unsigned int>> node_faces(nodes.size());
    for (unsigned int f = 0; f < faces.size(); ++f)
      face_vertices[f].assign(faces[f].nodes.begin(),
                              faces[f].nodes.begin() + faces[f].n_vertices);
    for (unsigned int n = 0; n < nodes.size(); ++n)
      node_faces[n] = nodes[n].faces;
    shapes.assign(faces.size(), SmoothedFace());
    stencils.assign(faces.size(), {});
    for (unsigned int f = 0; f < faces.size(); ++f)
    {
      const bool made = SmoothedFace::make(face_vertices,
                                           node_faces,
                                           f,
                                           faces[f].ring,
                                           shapes[f],
                                           stencils[f]);
      if (made)
        continue;
      // The face, for the error and the warning.
      const std::string what =
        " pair <" + pair.description.text + ">: a master face has " +
        std::to_string(faces[f].n_vertices + faces[f].ring.size()) +
        " nodes around it or a vertex shared by more than " +
        std::to_string(SmoothedFace::max_fan) + " faces, more than ";
      // Chosen by Master smoothing = automatic: the pair keeps its faces
      // rather than stopping a run whose user asked for no smoothing.
      AssertThrow(pair.description.smoothing_automatic,
                  ExcMessage("Contact" + what +
                             "Master smoothing = averaged normals supports "
                             "(at most " +
                             std::to_string(SmoothedFace::max_nodes) +
                             " nodes); use Master smoothing = none or a "
                             "more regular mesh."));
      faceted          = true;
      fallback_warning = "contact" + what +
                         "the averaged normals support: the master is met as "
                         "its faces (Contact/Master smoothing = automatic). A "
                         "more regular master mesh gets the smoothing, which "
                         "large sliding needs.";
      shapes.clear();
      stencils.clear();
      return;
    }
  }



  void
  SmoothedNodeToFaceDiscretization::stencil_positions(
    const unsigned int               face,
    const std::vector<Vec3<double>> &positions,
    Vec3<double>                    *x) const
  {
    const auto &stencil = stencils[face];
    for (unsigned int i = 0; i < stencil.size(); ++i)
      x[i] = positions[stencil[i]];
  }



  bool
  SmoothedNodeToFaceDiscretization::pair_node(ContactPair<3>    &pair,
                                              const unsigned int k)
  {
    if (faceted)
      return NodeToSegmentDiscretization<3>::pair_node(pair, k);
    NodeState          &state = pair.current[k];
    const Vec3<double> &x     = pair.slave_positions[k];

    // The smoothed projection onto face f: how far outside the face it
    // lies (0: inside, infinite: none).
    const auto try_face = [&](const unsigned int f, Projection &p) -> double
    {
      Vec3<double> xm[SmoothedFace::max_nodes];
      stencil_positions(f, pair.master_positions, xm);
      double xi[2], g;
      if (!shapes[f].project(x, xm, xi, g))
        return std::numeric_limits<double>::infinity();
      p       = Projection();
      p.xi[0] = xi[0];
      p.xi[1] = xi[1];
      Vec3<double> nodal[4], xbar, a[2], n, dn[2];
      shapes[f].nodal_normals(xm, nodal);
      shapes[f].field(xm, nodal, xi, xbar, a, n, dn);
      p.distance = norm(x - xbar);
      return shapes[f].outside(xi);
    };
    const auto accept = [&](const unsigned int f, const Projection &p)
    {
      state.face       = f;
      state.projection = p;
      state.paired     = true;
      return couple_face(pair, k);
    };

    // The face of the last evaluation while the node projects inside it:
    // the projection is continuous across edges, so this only saves the
    // search.
    if (state.paired && pair.face_known[state.face])
    {
      Projection p;
      if (try_face(state.face, p) <= 1e-12 &&
          p.distance <= parameters.search_distance)
        return accept(state.face, p);
    }
    state.paired   = false;
    state.face     = -1;
    state.distance = std::numeric_limits<double>::quiet_NaN();
    const std::vector<unsigned int> candidates =
      candidate_faces(pair, x, state);
    double     best_outside  = std::numeric_limits<double>::infinity();
    double     best_distance = std::numeric_limits<double>::max();
    int        best_face     = -1;
    Projection best;
    for (const unsigned int f : candidates)
    {
      Projection   p;
      const double outside = try_face(f, p);
      if (outside < best_outside ||
          (outside == best_outside && outside < 1e300 &&
           p.distance < best_distance))
      {
        best_outside  = outside;
        best_distance = p.distance;
        best_face     = f;
        best          = p;
      }
    }
    if (best_face < 0 || best_outside > edge_band)
      return false;
    // Outside every candidate but within the band: at a free edge of the
    // master the node sees the face's extension; between faces that
    // continue, the projection lies on the face up to round-off or on a
    // neighbour not among the candidates, and the nearest face serves.
    return accept(best_face, best);
  }



  void
  SmoothedNodeToFaceDiscretization::element_dofs(
    const ContactPair<3>                 &pair,
    const unsigned int                    k,
    const int                             face,
    std::vector<types::global_dof_index> &dofs) const
  {
    if (faceted)
      return NodeToSegmentDiscretization<3>::element_dofs(pair, k, face, dofs);
    const auto &slave_dofs = pair.slave->nodes()[k].dofs;
    dofs.assign(slave_dofs.begin(), slave_dofs.end());
    if (face >= 0)
      for (const unsigned int n : stencils[face])
        for (const auto dof : pair.master->nodes()[n].dofs)
          dofs.push_back(dof);
    pair.append_unknown_dofs(k, dofs);
  }



  ElementOutcome
  SmoothedNodeToFaceDiscretization::evaluate(
    ContactPair<3>                       &pair,
    const unsigned int                    k,
    const SlaveInput                     &slave,
    double                               *R,
    double                               *K,
    std::vector<types::global_dof_index> &dofs,
    std::string                          &refusal)
  {
    if (faceted)
      return NodeToSegmentDiscretization<3>::evaluate(pair,
                                                      k,
                                                      slave,
                                                      R,
                                                      K,
                                                      dofs,
                                                      refusal);
    NodeState        &state = pair.current[k];
    const int         face  = state.face;
    SmoothedFaceInput input;
    input.face = shapes[face];
    stencil_positions(face, pair.master_positions, input.x);
    const auto &vertices = pair.master->faces()[face].nodes;
    for (unsigned int v = 0; v < input.face.n_vertices; ++v)
      input.x_old[v] = pair.old_master_positions[vertices[v]];
    input.xi[0] = state.projection.xi[0];
    input.xi[1] = state.projection.xi[1];
    // The normal distance g of the converged projection (the projection
    // condition's third unknown).
    {
      Vec3<double> nodal[4], xbar, a[2], n, dn[2];
      input.face.nodal_normals(input.x, nodal);
      input.face.field(input.x, nodal, input.xi, xbar, a, n, dn);
      input.g = dot(slave.position - xbar, n) / dot(n, n);
    }
    // The face of the committed state, if its vertices are in the
    // stencil (the node moved on to it or to a neighbour).
    const int committed_face = pair.committed[k].face;
    if (committed_face >= 0)
    {
      const auto &f       = pair.master->faces()[committed_face];
      const auto &stencil = stencils[face];
      bool        found   = true;
      for (unsigned int v = 0; v < f.n_vertices && found; ++v)
      {
        const auto i = std::find(stencil.begin(), stencil.end(), f.nodes[v]);
        found        = i != stencil.end();
        input.committed_vertices[v] = i - stencil.begin();
        input.committed_old[v]      = pair.old_master_positions[f.nodes[v]];
      }
      input.n_committed_vertices = found ? f.n_vertices : 0;
    }
    state.result =
      NodeToSmoothedFace::evaluate(slave, input, *pair.enforcement, R, K);
    state.point = slave.position - scale(state.result.gap, state.result.normal);
    element_dofs(pair, k, face, dofs);
    return {ElementOutcome::Kind::element, true};
  }
} // namespace tribos
