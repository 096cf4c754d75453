#include <tribos/base/exceptions.h>
#include <tribos/contact/contact_handler.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/full_matrix.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>

namespace tribos
{
  template <int dim>
  ContactHandler<dim>::ContactHandler(
    const Parameters::Contact                       &parameters,
    const DoFHandler<dim>                           &dof_handler,
    const std::function<double(types::material_id)> &youngs_modulus,
    const IndexSet                                  &locally_owned_dofs,
    const MPI_Comm                                   mpi_communicator,
    const bool                                       axisymmetric)
    : parameters(parameters)
    , mpi_communicator(mpi_communicator)
    , consistent(parameters.tangent == "consistent")
    , all_contact_dofs(dof_handler.n_dofs())
    , n_displacement_dofs(dof_handler.n_dofs())
  {
    std::set<types::boundary_id> existing;
    for (const auto &face :
         dof_handler.get_triangulation().active_face_iterators())
      if (face->at_boundary())
        existing.insert(face->boundary_id());

    std::map<std::set<types::boundary_id>, std::shared_ptr<ContactSurface<dim>>>
               surfaces;
    const auto surface = [&](const std::set<unsigned int> &ids)
    {
      std::set<types::boundary_id> boundary_ids;
      for (const auto id : ids)
      {
        AssertThrow(existing.count(id) == 1,
                    ExcMessage("Parameter <Contact/Pairs> names boundary id " +
                               std::to_string(id) +
                               ", which the scene does not have. Its "
                               "boundary ids are listed in the README."));
        boundary_ids.insert(id);
      }
      auto &s = surfaces[boundary_ids];
      if (!s)
        s = std::make_shared<ContactSurface<dim>>(dof_handler,
                                                  boundary_ids,
                                                  axisymmetric);
      return s;
    };
    std::map<std::string, std::shared_ptr<RigidSurface<dim>>> rigid_surfaces;
    for (const auto &description : parameters.rigid_surfaces)
      rigid_surfaces[description.name] =
        std::make_shared<RigidSurface<dim>>(description);

    std::vector<Parameters::ContactPair> descriptions = parameters.pairs;
    if (parameters.passes == "two-pass")
      for (const auto &p : parameters.pairs)
        if (p.rigid_surface.empty())
        {
          auto swapped            = p;
          swapped.slave_boundary  = p.master_boundary;
          swapped.master_boundary = p.slave_boundary;
          swapped.text            = p.text + " (second pass)";
          descriptions.push_back(swapped);
        }

    // Hanging-node constraints: a slave node on a refinement border whose
    // position follows its parents carries no multiplier of its own.
    AffineConstraints<double> hanging_constraints;
    DoFTools::make_hanging_node_constraints(dof_handler, hanging_constraints);
    hanging_constraints.close();

    for (const auto &description : descriptions)
    {
      Pair pair;
      pair.description = description;
      pair.lagrange    = description.method == "lagrange multiplier";
      AssertThrow(!pair.lagrange || parameters.passes != "two-pass",
                  ExcMessage("Contact/Passes = two-pass with Contact/Method "
                             "= lagrange multiplier: node-to-segment "
                             "constraints of both passes over-constrain the "
                             "interface (singular system). Use one-pass."));
      pair.slave = surface(description.slave_boundary);
      // The contact modulus: the series modulus E_s E_m / (E_s + E_m) of
      // the two sides, E_s against a rigid surface (its limit). It is
      // continuous at that limit and, like Hertz's E*, it is set by the
      // softer side when the moduli differ much (a penalty on the stiffer
      // side's scale would make soft-on-hard contact ill-conditioned).
      double E_s = std::numeric_limits<double>::max();
      for (const auto body : pair.slave->bodies())
        E_s = std::min(E_s, youngs_modulus(body));
      double E = E_s;
      if (description.rigid_surface.empty())
      {
        pair.master = surface(description.master_boundary);
        double E_m  = std::numeric_limits<double>::max();
        for (const auto body : pair.master->bodies())
          E_m = std::min(E_m, youngs_modulus(body));
        E                = E_s * E_m / (E_s + E_m);
        pair.area_factor = (parameters.passes == "two-pass" ? 0.5 : 1.);
      }
      else
        pair.rigid = rigid_surfaces.at(description.rigid_surface);

      pair.contact_modulus          = E;
      pair.law.friction_coefficient = description.friction_coefficient;

      const unsigned int n_slaves = pair.slave->nodes().size();
      pair.owned.resize(n_slaves);
      for (unsigned int k = 0; k < n_slaves; ++k)
        pair.owned[k] =
          locally_owned_dofs.is_element(pair.slave->nodes()[k].dofs[0]);
      pair.history.resize(n_slaves);
      for (unsigned int k = 0; k < n_slaves; ++k)
        pair.history[k].point = pair.slave->nodes()[k].reference;
      pair.multipliers.assign(n_slaves, 0.);
      pair.area.resize(n_slaves);
      for (unsigned int k = 0; k < n_slaves; ++k)
        pair.area[k] = pair.slave->nodes()[k].area * pair.area_factor;
      pair.excluded.assign(n_slaves, false);
      if (pair.lagrange)
        exclude_dependent_nodes(pair, hanging_constraints);
      if (pair.lagrange)
      {
        pair.first_multiplier = dof_handler.n_dofs() + n_multiplier_dofs;
        n_multiplier_dofs += dim * n_slaves;
        pair.lagrange_values.assign(n_slaves, {{0, 0, 0}});
      }
      pair.committed_multipliers.assign(n_slaves, 0.);
      pair.pairing.resize(n_slaves);
      pair.results.resize(n_slaves);
      for (const auto &node : pair.slave->nodes())
        pair.slave_positions.push_back(node.reference);
      pair.old_slave_positions = pair.slave_positions;
      if (pair.master)
        for (const auto &node : pair.master->nodes())
          pair.master_positions.push_back(node.reference);
      pair.old_master_positions = pair.master_positions;
      pairs.push_back(std::move(pair));
    }

    for (const auto &[id, s] : surfaces)
      for (const auto &node : s->nodes())
        for (const auto dof : node.dofs)
          all_contact_dofs.add_index(dof);
    all_contact_dofs.compress();
  }



  template <int dim>
  void
  ContactHandler<dim>::exclude_dependent_nodes(
    Pair                            &pair,
    const AffineConstraints<double> &hanging_constraints)
  {
    const auto                                     &nodes = pair.slave->nodes();
    const unsigned int                              n_slaves = nodes.size();
    std::map<types::global_dof_index, unsigned int> node_of_dof;
    for (unsigned int k = 0; k < n_slaves; ++k)
      node_of_dof[nodes[k].dofs[0]] = k;

    // A hanging slave node: its constraint row would be the combination of
    // its parents' rows (a singular saddle-point system). It carries no
    // multiplier; its tributary area goes to its parents with the
    // constraint's weights, so that the multipliers stay tractions.
    for (unsigned int k = 0; k < n_slaves; ++k)
    {
      const auto dof = nodes[k].dofs[0];
      if (!hanging_constraints.is_constrained(dof))
        continue;
      const auto *entries = hanging_constraints.get_constraint_entries(dof);
      if (entries == nullptr || entries->empty())
        continue;
      pair.excluded[k] = true;
      double moved     = 0;
      for (const auto &[parent_dof, weight] : *entries)
      {
        const auto parent = node_of_dof.find(parent_dof);
        if (parent != node_of_dof.end())
        {
          pair.area[parent->second] += weight * pair.area[k];
          moved += weight;
        }
      }
      AssertThrow(std::abs(moved - 1.) < 1e-8,
                  ExcMessage("Contact pair <" + pair.description.text +
                             ">: a hanging slave node whose parents are not "
                             "on the slave surface; refine the slave surface "
                             "as a whole."));
      pair.area[k] = 0;
    }

    // A node that an earlier Lagrange pair already constrains against the
    // same master (an edge shared by two slave surfaces, e.g. the top and
    // the side of an upset cylinder) would get a second, identical
    // constraint: it is left to the earlier pair, which takes over its
    // tributary area here. Writing both parts as one slave surface
    // ('3, 4 : plate') avoids the duplicate altogether.
    for (auto &other : pairs)
    {
      if (!other.lagrange ||
          other.description.rigid_surface != pair.description.rigid_surface ||
          other.description.master_boundary != pair.description.master_boundary)
        continue;
      std::map<unsigned int, unsigned int> other_node_of_vertex;
      for (unsigned int j = 0; j < other.slave->nodes().size(); ++j)
        other_node_of_vertex[other.slave->nodes()[j].vertex] = j;
      for (unsigned int k = 0; k < n_slaves; ++k)
      {
        const auto j = other_node_of_vertex.find(nodes[k].vertex);
        if (j == other_node_of_vertex.end() || pair.excluded[k])
          continue;
        pair.excluded[k] = true;
        if (!other.excluded[j->second])
          other.area[j->second] += pair.area[k];
        pair.area[k] = 0;
      }
    }
  }



  /**
   * Width, in local coordinates, of the band beyond the end of a master
   * surface in which a slave node still sees the end face's extension.
   */
  constexpr double edge_band = 0.1;



  template <int dim>
  void
  ContactHandler<dim>::update(const TrilinosWrappers::MPI::Vector &solution,
                              const double                         t)
  {
    time                    = t;
    bool       new_coupling = false;
    const auto positions =
      [&solution](const auto &surface, std::vector<Vec3<double>> &x)
    {
      const auto &nodes = surface.nodes();
      for (unsigned int k = 0; k < nodes.size(); ++k)
      {
        x[k] = nodes[k].reference;
        for (unsigned int d = 0; d < dim; ++d)
          x[k][d] += solution[nodes[k].dofs[d]];
      }
    };

    for (auto &pair : pairs)
    {
      positions(*pair.slave, pair.slave_positions);
      // The multipliers are unknowns of the system: read them here.
      if (pair.lagrange)
        for (unsigned int k = 0; k < pair.owned.size(); ++k)
          for (unsigned int d = 0; d < dim; ++d)
            pair.lagrange_values[k][d] =
              solution[pair.first_multiplier + dim * k + d];
      if (pair.rigid)
      {
        for (unsigned int k = 0; k < pair.owned.size(); ++k)
          pair.pairing[k].valid = pair.owned[k] && !pair.excluded[k];
        continue;
      }
      positions(*pair.master, pair.master_positions);
      pair.search.build(*pair.master, pair.master_positions);

      const auto &faces = pair.master->faces();
      for (unsigned int k = 0; k < pair.owned.size(); ++k)
      {
        Pairing &pairing = pair.pairing[k];
        if (!pair.owned[k] || pair.excluded[k])
          continue;
        if (smoothed(pair))
          pair_smoothed(pair, k);
        else
          pair_faceted(pair, k);

        if (pairing.face >= 0 && pair.couplings.count({k, pairing.face}) == 0)
        {
          new_coupling = true;
          pair.couplings.insert({k, pairing.face});
          for (const unsigned int g : faces[pairing.face].neighbours)
            pair.couplings.insert({k, g});
        }
      }
    }
    if (Utilities::MPI::max(new_coupling ? 1 : 0, mpi_communicator) == 1)
      outdated = true;
  }



  template <int dim>
  bool
  ContactHandler<dim>::smoothed(const Pair &pair) const
  {
    return dim == 2 && pair.master && parameters.smoothing != "none";
  }



  template <int dim>
  void
  ContactHandler<dim>::smoothed_stencil(
    const Pair                      &pair,
    const unsigned int               face,
    const std::vector<Vec3<double>> &positions,
    Vec3<double>                    *x,
    bool                            *has) const
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



  template <int dim>
  void
  ContactHandler<dim>::pair_faceted(Pair &pair, const unsigned int k) const
  {
    Pairing            &pairing = pair.pairing[k];
    const Vec3<double> &x       = pair.slave_positions[k];
    const auto         &faces   = pair.master->faces();
    const auto project_onto     = [&](const unsigned int f, const bool clamp)
    {
      Vec3<double> xm[4];
      for (unsigned int v = 0; v < MasterFace<dim>::n_nodes; ++v)
        xm[v] = pair.master_positions[faces[f].nodes[v]];
      return project<dim>(x, xm, clamp);
    };

    // Keep the face of the last evaluation while the node projects
    // onto it or onto its extension within a small band: over a
    // master vertex (a concave kink of the deformed master) the
    // closest face would otherwise flip between iterations and
    // Newton would cycle between two smooth residuals.
    if (pairing.valid)
    {
      const Projection kept = project_onto(pairing.face, false);
      bool             near = kept.distance <= parameters.search_distance;
      for (unsigned int c = 0; c < dim - 1; ++c)
        near = near && std::abs(kept.xi[c]) <= 1. + edge_band;
      if (near)
      {
        pairing.projection = kept;
        return;
      }
    }
    pairing = Pairing();
    const std::vector<unsigned int> candidates =
      candidate_faces(pair, x, pairing);
    if (candidates.empty())
      return;

    // Exact projection on the candidate and its neighbours: prefer
    // a projection inside a face (the closest such), else the
    // closest clamped one.
    bool   best_inside   = false;
    double best_distance = std::numeric_limits<double>::max();
    for (const unsigned int f : candidates)
    {
      const Projection p      = project_onto(f, true);
      const bool       inside = p.inside();
      if ((inside && !best_inside) ||
          (inside == best_inside && p.distance < best_distance))
      {
        best_inside        = inside;
        best_distance      = p.distance;
        pairing.face       = f;
        pairing.projection = p;
      }
    }
    // A projection clamped at an edge where the master surface ends:
    // within a small band beyond the edge the node sees the face's
    // extension (a smooth residual for nodes flush with the end of
    // the master); farther out it has slid off: no contact.
    pairing.valid = true;
    bool at_end   = false;
    for (unsigned int c = 0; c < dim - 1; ++c)
      if (pairing.projection.clamped[c] != 0 &&
          !faces[pairing.face].continues[c][pairing.projection.clamped[c] > 0])
        at_end = true;
    if (at_end)
    {
      const Projection extended = project_onto(pairing.face, false);
      for (unsigned int c = 0; c < dim - 1; ++c)
        if (std::abs(extended.xi[c]) > 1. + edge_band)
          pairing.valid = false;
      pairing.projection = extended;
    }
  }



  template <int dim>
  std::vector<unsigned int>
  ContactHandler<dim>::candidate_faces(const Pair         &pair,
                                       const Vec3<double> &x,
                                       Pairing            &pairing) const
  {
    unsigned int closest;
    double       squared_distance;
    if (!pair.search.closest_face(x, closest, squared_distance))
      return {};
    pairing.distance = std::sqrt(squared_distance);
    if (pairing.distance > parameters.search_distance)
      return {};
    std::vector<unsigned int> candidates =
      pair.master->faces()[closest].neighbours;
    candidates.insert(candidates.begin(), closest);
    return candidates;
  }



  template <int dim>
  void
  ContactHandler<dim>::pair_smoothed(Pair &pair, const unsigned int k) const
  {
    Pairing            &pairing = pair.pairing[k];
    const Vec3<double> &x       = pair.slave_positions[k];
    const auto         &faces   = pair.master->faces();

    // The smoothed projection onto one face: inside, or on the extension
    // beyond a free end of the master within the edge band.
    const auto try_face = [&](const unsigned int f, Projection &p) -> int
    {
      Vec3<double> xm[4];
      bool         has[2];
      smoothed_stencil(pair, f, pair.master_positions, xm, has);
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
    // it: the projection is continuous across vertices, so this only
    // saves the search.
    if (pairing.valid)
    {
      Projection p;
      const int  kind = try_face(pairing.face, p);
      if (kind > 0 && p.distance <= parameters.search_distance)
      {
        pairing.projection = p;
        return;
      }
    }
    pairing              = Pairing();
    int    best_kind     = 0;
    double best_distance = std::numeric_limits<double>::max();
    for (const unsigned int f : candidate_faces(pair, x, pairing))
    {
      Projection p;
      const int  kind = try_face(f, p);
      if (kind > best_kind ||
          (kind == best_kind && kind > 0 && p.distance < best_distance))
      {
        best_kind          = kind;
        best_distance      = p.distance;
        pairing.face       = f;
        pairing.projection = p;
      }
    }
    pairing.valid = best_kind > 0;
  }



  template <int dim>
  void
  ContactHandler<dim>::element_dofs(
    const Pair                           &pair,
    const unsigned int                    node,
    const int                             face,
    std::vector<types::global_dof_index> &dofs) const
  {
    const auto &slave_dofs = pair.slave->nodes()[node].dofs;
    dofs.assign(slave_dofs.begin(), slave_dofs.end());
    if (pair.master && face >= 0)
    {
      for (const unsigned int m : pair.master->faces()[face].nodes)
        for (const auto dof : pair.master->nodes()[m].dofs)
          dofs.push_back(dof);
      if (smoothed(pair))
        for (const int m : pair.master->faces()[face].beyond)
          if (m >= 0)
            for (const auto dof : pair.master->nodes()[m].dofs)
              dofs.push_back(dof);
    }
    if (pair.lagrange)
      for (unsigned int d = 0; d < dim; ++d)
        dofs.push_back(pair.first_multiplier + dim * node + d);
  }



  template <int dim>
  void
  ContactHandler<dim>::add_couplings(
    DynamicSparsityPattern          &dsp,
    const AffineConstraints<double> &constraints)
  {
    outdated = false;
    for (const auto &pair : pairs)
    {
      std::vector<types::global_dof_index> dofs;
      for (const auto &[k, f] : pair.couplings)
      {
        element_dofs(pair, k, f, dofs);
        constraints.add_entries_local_to_global(dofs, dsp, false);
      }
      // A multiplier row exists for every slave node, paired or not.
      if (pair.lagrange)
        for (unsigned int k = 0; k < pair.owned.size(); ++k)
          if (pair.owned[k])
          {
            element_dofs(pair, k, -1, dofs);
            constraints.add_entries_local_to_global(dofs, dsp, false);
          }
    }
  }



  template <int dim>
  void
  ContactHandler<dim>::assemble(const bool                       with_matrix,
                                const AffineConstraints<double> &constraints,
                                const AffineConstraints<double> &homogeneous,
                                TrilinosWrappers::SparseMatrix  &matrix,
                                TrilinosWrappers::MPI::Vector   &rhs,
                                TrilinosWrappers::MPI::Vector   &free_residual,
                                TrilinosWrappers::MPI::Vector   &full_residual,
                                TrilinosWrappers::MPI::Vector   &contact_forces)
  {
    constexpr unsigned int n_max =
      std::max(NodeToSegment<dim>::n_dofs, NodeToSmoothedSegment::max_dofs) +
      dim;
    double             R[n_max], K[n_max * n_max];
    const Vec3<double> zero{{0, 0, 0}};

    for (auto &pair : pairs)
    {
      const Vec3<double> shift =
        pair.rigid ? pair.rigid->translation(time) : zero;
      const Vec3<double> old_shift =
        pair.rigid ? pair.rigid->translation(committed_time) : zero;
      // Element buffers, reused for every slave node of the pair (sized
      // per element by add()).
      std::vector<types::global_dof_index> dofs;
      dealii::Vector<double>               local_rhs, local_residual;
      FullMatrix<double>                   local_matrix;

      std::vector<types::global_dof_index> force_dofs;
      std::vector<double>                  local_force;
      const auto                           add = [&](const unsigned int n)
      {
        local_rhs.reinit(n);
        local_residual.reinit(n);
        for (unsigned int i = 0; i < n; ++i)
        {
          local_rhs(i)      = -R[i];
          local_residual(i) = R[i];
        }
        full_residual.add(dofs, local_residual);
        // The forces on the nodes: the displacement rows only.
        force_dofs.clear();
        local_force.clear();
        for (unsigned int i = 0; i < n; ++i)
          if (dofs[i] < n_displacement_dofs)
          {
            force_dofs.push_back(dofs[i]);
            local_force.push_back(-R[i]);
          }
        if (!force_dofs.empty())
          contact_forces.add(force_dofs, local_force);
        homogeneous.distribute_local_to_global(local_rhs, dofs, free_residual);
        if (with_matrix)
        {
          local_matrix.reinit(n, n);
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              local_matrix(i, j) = K[i * n + j];
          constraints.distribute_local_to_global(local_matrix,
                                                 local_rhs,
                                                 dofs,
                                                 matrix,
                                                 rhs);
        }
      };

      for (unsigned int k = 0; k < pair.owned.size(); ++k)
      {
        pair.results[k]   = ContactPointResult();
        const double area = pair.area[k];
        if (!pair.pairing[k].valid)
        {
          // Off the master (beyond its end or the search distance): the
          // distance to the master surface, a positive, open gap.
          pair.results[k].gap = pair.pairing[k].distance;
          // An unpaired or excluded node of a Lagrange pair: Lambda = 0,
          // scaled by the node's own tributary area (an excluded node has
          // handed its area to others).
          if (pair.lagrange && pair.owned[k])
          {
            const double scale = pair.slave->nodes()[k].area * pair.area_factor;
            element_dofs(pair, k, -1, dofs);
            dofs.erase(dofs.begin(), dofs.begin() + dim);
            for (unsigned int i = 0; i < dim; ++i)
            {
              R[i] = scale * pair.lagrange_values[k][i];
              for (unsigned int j = 0; j < dim; ++j)
                K[i * dim + j] = (i == j ? scale : 0.);
            }
            add(dim);
          }
          continue;
        }
        const SlaveHistory &history = pair.history[k];
        const ContactLaw    law     = node_law(pair, k, homogeneous);
        const Vec3<double> &x       = pair.slave_positions[k];
        const Vec3<double> *lambda =
          pair.lagrange ? &pair.lagrange_values[k] : nullptr;

        if (smoothed(pair))
        {
          const int    face = pair.pairing[k].face;
          Vec3<double> xm[4], xm_old[4];
          bool         has[2];
          smoothed_stencil(pair, face, pair.master_positions, xm, has);
          smoothed_stencil(pair, face, pair.old_master_positions, xm_old, has);
          pair.results[k] =
            NodeToSmoothedSegment::evaluate(x,
                                            xm,
                                            has,
                                            pair.pairing[k].projection.xi[0],
                                            xm_old,
                                            history,
                                            law,
                                            area,
                                            consistent,
                                            R,
                                            K,
                                            lambda);
          pair.results[k].face = face;
        }
        else if (pair.master)
        {
          const auto  &faces = pair.master->faces();
          const int    face  = pair.pairing[k].face;
          Vec3<double> xm[4], xm_old[4];
          for (unsigned int v = 0; v < MasterFace<dim>::n_nodes; ++v)
          {
            xm[v]     = pair.master_positions[faces[face].nodes[v]];
            xm_old[v] = pair.old_master_positions[faces[face].nodes[v]];
          }
          pair.results[k] =
            NodeToSegment<dim>::evaluate(x,
                                         xm,
                                         pair.pairing[k].projection,
                                         xm_old,
                                         history,
                                         history.face == face,
                                         law,
                                         area,
                                         consistent,
                                         R,
                                         K,
                                         lambda);
          pair.results[k].face = face;
        }
        else
        {
          pair.results[k] = NodeToRigid<dim>::evaluate(x,
                                                       *pair.rigid,
                                                       shift,
                                                       old_shift,
                                                       history,
                                                       law,
                                                       area,
                                                       consistent,
                                                       R,
                                                       K,
                                                       lambda);
        }

        if (!pair.rigid || pair.results[k].gap <= parameters.search_distance)
          pair.ever_near = true;
        if (!pair.lagrange && pair.results[k].status == ContactStatus::open)
          continue;

        // The element's size: its master nodes (with smoothing also the
        // segment's neighbours) and multipliers.
        element_dofs(pair, k, pair.pairing[k].face, dofs);
        const unsigned int n_element = dofs.size();
        if (pair.lagrange)
          guard_constraint_rows(dofs,
                                n_element - dim,
                                homogeneous,
                                area,
                                pair.lagrange_values[k],
                                R,
                                K);
        add(n_element);
      }
    }
  }



  template <int dim>
  ContactLaw
  ContactHandler<dim>::node_law(
    const Pair                      &pair,
    const unsigned int               k,
    const AffineConstraints<double> &homogeneous) const
  {
    const auto  &node  = pair.slave->nodes()[k];
    const double E     = pair.contact_modulus;
    ContactLaw   law   = pair.law;
    law.normal_penalty = pair.description.normal_penalty.resolve(E, node.size);
    // Multipliers: the semismooth stick/slip parameter c_T instead of the
    // tangential penalty.
    law.tangential_penalty =
      pair.lagrange ?
        parameters.friction_complementarity.resolve(E, node.size) :
        pair.description.tangential_penalty.resolve(E, node.size);
    law.multiplier    = pair.multipliers[k];
    law.frozen_closed = k < pair.frozen.size() && pair.frozen[k];
    if (pair.lagrange)
      for (unsigned int d = 0; d < dim; ++d)
        if (homogeneous.is_constrained(node.dofs[d]) &&
            homogeneous.get_constraint_entries(node.dofs[d])->empty())
          law.fixed_components |= (1u << d);
    return law;
  }



  template <int dim>
  void
  ContactHandler<dim>::guard_constraint_rows(
    const std::vector<types::global_dof_index> &dofs,
    const unsigned int                          n_displacements,
    const AffineConstraints<double>            &homogeneous,
    const double                                area,
    const Vec3<double>                         &lambda,
    double                                     *R,
    double                                     *K) const
  {
    // A constraint row that depends on no free unknown (e.g. a slave node
    // fixed by Dirichlet conditions pressed onto a rigid surface, or whose
    // only free motion on an inclined symmetry plane is tangential to the
    // gap) would make the system singular: its multiplier does no work on
    // any free dof, so it is set to zero (the reaction goes to the
    // constraints instead). The test is on the row as the solver sees it,
    // condensed through the constraints (u_j = sum_k c_jk u_k): entries of
    // different constrained columns may cancel on the same free dof.
    const unsigned int                        n = n_displacements + dim;
    std::map<types::global_dof_index, double> condensed;
    for (unsigned int i = n_displacements; i < n; ++i)
    {
      condensed.clear();
      double scale = 0;
      for (unsigned int j = 0; j < n; ++j)
      {
        const double entry = K[i * n + j];
        scale              = std::max(scale, std::abs(entry));
        if (j >= n_displacements || !homogeneous.is_constrained(dofs[j]))
          condensed[dofs[j]] += entry;
        else
          for (const auto &e : *homogeneous.get_constraint_entries(dofs[j]))
            condensed[e.first] += entry * e.second;
      }
      double free = 0;
      for (const auto &[dof, value] : condensed)
        free = std::max(free, std::abs(value));
      if (free > 1e-10 * scale)
        continue;
      const unsigned int d = i - n_displacements;
      R[i]                 = area * lambda[d];
      for (unsigned int j = 0; j < n; ++j)
        K[i * n + j] = (j == i ? area : 0.);
    }
  }



  template <int dim>
  void
  ContactHandler<dim>::commit()
  {
    for (auto &pair : pairs)
    {
      for (unsigned int k = 0; k < pair.owned.size(); ++k)
      {
        if (!pair.owned[k])
          continue;
        const auto &result  = pair.results[k];
        auto       &history = pair.history[k];
        history.active      = result.status != ContactStatus::open;
        if (history.active)
        {
          history.traction = result.traction;
          history.slip += result.slip_increment;
        }
        else
          history.traction = {{0, 0, 0}};
        // Where the node was: its projection point and frame on the
        // master, or (unpaired) the node itself.
        const Vec3<double> &x = pair.slave_positions[k];
        if (pair.pairing[k].valid)
        {
          history.point  = x - scale(result.gap, result.normal);
          history.normal = result.normal;
          history.face   = result.face;
          history.xi[0]  = result.xi[0];
          history.xi[1]  = result.xi[1];
        }
        else
        {
          history.point  = x;
          history.normal = {{0, 0, 0}};
          history.face   = -1;
        }
      }
      pair.old_slave_positions   = pair.slave_positions;
      pair.old_master_positions  = pair.master_positions;
      pair.committed_multipliers = pair.multipliers;
    }
    committed_time = time;
  }



  template <int dim>
  void
  ContactHandler<dim>::restore()
  {
    for (auto &pair : pairs)
      pair.multipliers = pair.committed_multipliers;
  }



  template <int dim>
  void
  ContactHandler<dim>::begin_increment()
  {
    for (auto &pair : pairs)
    {
      pair.tracked_status.assign(pair.owned.size(), -1);
      pair.status_changes.assign(pair.owned.size(), 0);
      pair.frozen.assign(pair.owned.size(), false);
    }
  }



  template <int dim>
  unsigned int
  ContactHandler<dim>::freeze_chattering(const unsigned int limit)
  {
    unsigned int n = 0;
    for (auto &pair : pairs)
      for (unsigned int k = 0; k < pair.owned.size(); ++k)
        if (pair.owned[k] && pair.status_changes[k] > limit)
        {
          pair.frozen[k] = true;
          ++n;
        }
    return Utilities::MPI::sum(n, mpi_communicator);
  }



  template <int dim>
  unsigned int
  ContactHandler<dim>::n_frozen_in_tension() const
  {
    unsigned int n = 0;
    for (const auto &pair : pairs)
      for (unsigned int k = 0; k < pair.frozen.size(); ++k)
        if (pair.frozen[k] && pair.owned[k] &&
            (pair.results[k].pressure < 0 || !pair.pairing[k].valid))
          ++n;
    return Utilities::MPI::sum(n, mpi_communicator);
  }



  template <int dim>
  unsigned int
  ContactHandler<dim>::track_status_changes(const unsigned int limit)
  {
    unsigned int n_chattering = 0;
    for (auto &pair : pairs)
    {
      if (pair.tracked_status.size() != pair.owned.size())
      {
        pair.tracked_status.assign(pair.owned.size(), -1);
        pair.status_changes.assign(pair.owned.size(), 0);
      }
      for (unsigned int k = 0; k < pair.owned.size(); ++k)
        if (pair.owned[k])
        {
          // Contact status only (open or closed): stick/slip changes
          // are the return map's business and converge.
          const int status =
            pair.results[k].status == ContactStatus::open ? 0 : 1;
          if (pair.tracked_status[k] >= 0 && status != pair.tracked_status[k])
          {
            ++pair.status_changes[k];
          }
          pair.tracked_status[k] = status;
          if (pair.status_changes[k] > limit)
            ++n_chattering;
        }
    }
    return Utilities::MPI::sum(n_chattering, mpi_communicator);
  }



  template <int dim>
  bool
  ContactHandler<dim>::augmented() const
  {
    for (const auto &pair : pairs)
      if (pair.description.method == "augmented lagrangian")
        return true;
    return false;
  }



  template <int dim>
  double
  ContactHandler<dim>::augment(const double tolerance)
  {
    double violation = 0;
    for (const auto &pair : pairs)
      if (pair.description.method == "augmented lagrangian")
        for (unsigned int k = 0; k < pair.owned.size(); ++k)
          if (pair.owned[k] && pair.results[k].status != ContactStatus::open)
          {
            const double size = pair.slave->nodes()[k].size;
            // Closed nodes must touch: a gap of either sign is a
            // violation (a positive one means the warm-started multiplier
            // of an unloading node is too large).
            violation =
              std::max(violation, std::abs(pair.results[k].gap) / size);
          }
    violation = Utilities::MPI::max(violation, mpi_communicator);
    if (violation > tolerance)
      for (auto &pair : pairs)
        if (pair.description.method == "augmented lagrangian")
          for (unsigned int k = 0; k < pair.owned.size(); ++k)
            pair.multipliers[k] = pair.results[k].pressure;
    return violation;
  }



  template <int dim>
  ContactStatistics
  ContactHandler<dim>::statistics() const
  {
    ContactStatistics s;
    for (const auto &pair : pairs)
    {
      std::array<double, 5> forces = {{0, 0, 0, 0, 0}};
      for (unsigned int k = 0; k < pair.owned.size(); ++k)
      {
        const auto &r = pair.results[k];
        if (!pair.owned[k] || r.status == ContactStatus::open)
          continue;
        const double area = pair.area[k];
        forces[0] += area * r.pressure;
        forces[1] += area * norm(r.traction);
        for (unsigned int d = 0; d < 3; ++d)
          forces[2 + d] += area * (r.pressure * r.normal[d] - r.traction[d]);
        s.max_penetration = std::max(s.max_penetration, -r.gap);
        ++s.n_active;
        if (r.status == ContactStatus::stick)
          ++s.n_stick;
        else if (r.status == ContactStatus::slip)
          ++s.n_slip;
      }
      for (auto &f : forces)
        f = Utilities::MPI::sum(f, mpi_communicator);
      s.pair_forces.push_back(forces);
    }
    s.max_penetration =
      Utilities::MPI::max(s.max_penetration, mpi_communicator);
    s.n_active = Utilities::MPI::sum(s.n_active, mpi_communicator);
    s.n_stick  = Utilities::MPI::sum(s.n_stick, mpi_communicator);
    s.n_slip   = Utilities::MPI::sum(s.n_slip, mpi_communicator);
    return s;
  }



  template <int dim>
  std::vector<std::string>
  ContactHandler<dim>::setup_warnings() const
  {
    std::vector<std::string> warnings;
    for (const auto &pair : pairs)
    {
      const auto check =
        [&](const Parameters::PenaltyValue &penalty, const std::string &what)
      {
        // k = eps h / E at every slave node.
        double k_min = std::numeric_limits<double>::max(), k_max = 0;
        for (const auto &node : pair.slave->nodes())
        {
          const double k = penalty.resolve(pair.contact_modulus, node.size) *
                           node.size / pair.contact_modulus;
          k_min = std::min(k_min, k);
          k_max = std::max(k_max, k);
        }
        if (k_min < 1e-3 || k_max > 1e8)
          warnings.push_back(
            "contact pair <" + pair.description.text + ">: the " + what +
            " is " + to_scientific(k_min) + " to " + to_scientific(k_max) +
            " E/h over its slave nodes, outside [1e-3, 1e8] E/h (E = " +
            to_scientific(pair.contact_modulus) + "): " +
            (k_min < 1e-3 ? "too soft to keep the bodies apart" :
                            "stiffer than round-off allows Newton to resolve") +
            " (Contact/" +
            (what == "normal penalty" ? "Penalty factor" :
                                        "Tangential penalty factor") +
            " or the pair's option).");
      };
      if (pair.lagrange)
        continue;
      check(pair.description.normal_penalty, "normal penalty");
      if (pair.description.friction_coefficient > 0)
        check(pair.description.tangential_penalty, "tangential penalty");
    }
    return warnings;
  }



  template <int dim>
  std::vector<std::string>
  ContactHandler<dim>::describe() const
  {
    std::vector<std::string> lines;
    for (const auto &pair : pairs)
    {
      double h_min = std::numeric_limits<double>::max(), h_max = 0;
      for (const auto &node : pair.slave->nodes())
      {
        h_min = std::min(h_min, node.size);
        h_max = std::max(h_max, node.size);
      }
      const auto &penalty = pair.description.normal_penalty;
      lines.push_back(
        "contact pair <" + pair.description.text +
        ">: " + pair.description.method + ", " +
        std::to_string(pair.slave->nodes().size()) +
        " slave nodes, contact modulus E = " +
        to_scientific(pair.contact_modulus) + ", h = " + to_scientific(h_min) +
        " to " + to_scientific(h_max) + ", eps_N = " +
        to_scientific(penalty.resolve(pair.contact_modulus, h_max)) + " to " +
        to_scientific(penalty.resolve(pair.contact_modulus, h_min)));
    }
    return lines;
  }



  template <int dim>
  std::vector<std::string>
  ContactHandler<dim>::run_warnings() const
  {
    std::vector<std::string> warnings;
    for (const auto &pair : pairs)
      if (Utilities::MPI::max(pair.ever_near ? 1 : 0, mpi_communicator) == 0)
        warnings.push_back(
          "contact pair <" + pair.description.text +
          ">: no slave node came within the search distance of the master "
          "during the run (Contact/Search distance = " +
          to_scientific(parameters.search_distance) +
          "); check the pair's boundary ids and the surfaces' positions.");
    return warnings;
  }



  template <int dim>
  std::vector<std::string>
  ContactHandler<dim>::column_names() const
  {
    std::vector<std::string> names;
    const char              *axis = "xyz";
    for (unsigned int p = 0; p < pairs.size(); ++p)
    {
      const std::string prefix = "pair" + std::to_string(p) + "_";
      names.push_back(prefix + "normal_force");
      names.push_back(prefix + "tangential_force");
      for (unsigned int d = 0; d < dim; ++d)
        names.push_back(prefix + "F" + axis[d]);
    }
    for (const std::string name :
         {"max_penetration", "n_active", "n_stick", "n_slip"})
      names.push_back(name);
    return names;
  }



  template <int dim>
  std::vector<double>
  ContactHandler<dim>::columns() const
  {
    const ContactStatistics s = statistics();
    std::vector<double>     values;
    for (const auto &forces : s.pair_forces)
      for (unsigned int i = 0; i < 2 + dim; ++i)
        values.push_back(forces[i]);
    values.push_back(s.max_penetration);
    values.push_back(s.n_active);
    values.push_back(s.n_stick);
    values.push_back(s.n_slip);
    return values;
  }



  template <int dim>
  void
  ContactHandler<dim>::write_csv(const std::string &filename) const
  {
    // One row per slave node: pair, body, x, y, z, CPRESS, CSHEAR (3),
    // COPEN, CSLIP, CSTATUS.
    constexpr unsigned int n_columns = 13;
    std::vector<double>    rows;
    for (unsigned int p = 0; p < pairs.size(); ++p)
    {
      const auto &pair = pairs[p];
      for (unsigned int k = 0; k < pair.owned.size(); ++k)
      {
        if (!pair.owned[k])
          continue;
        const auto  &r    = pair.results[k];
        const auto  &x    = pair.slave_positions[k];
        const auto  &node = pair.slave->nodes()[k];
        const auto   body = pair.slave->faces()[node.faces[0]].body;
        const double values[n_columns] = {double(p),
                                          double(body),
                                          x[0],
                                          x[1],
                                          x[2],
                                          r.pressure,
                                          -r.traction[0],
                                          -r.traction[1],
                                          -r.traction[2],
                                          r.gap,
                                          pair.history[k].slip,
                                          double(int(r.status)),
                                          double(k)};
        rows.insert(rows.end(), values, values + n_columns);
      }
    }
    const auto gathered = Utilities::MPI::gather(mpi_communicator, rows, 0);
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;

    // Sort by pair and node so that the file does not depend on the
    // partition.
    std::vector<std::array<double, n_columns>> all;
    for (const auto &part : gathered)
      for (unsigned int i = 0; i < part.size(); i += n_columns)
      {
        std::array<double, n_columns> row;
        std::copy(part.begin() + i, part.begin() + i + n_columns, row.begin());
        all.push_back(row);
      }
    std::sort(all.begin(),
              all.end(),
              [](const auto &a, const auto &b)
              { return a[0] != b[0] ? a[0] < b[0] : a[12] < b[12]; });

    const std::string temporary = filename + ".part";
    {
      std::ofstream out(temporary);
      AssertThrow(out, ExcMessage("Cannot write <" + temporary + ">."));
      out << "pair,body,x,y,z,CPRESS,CSHEAR_x,CSHEAR_y,CSHEAR_z,COPEN,CSLIP,"
             "CSTATUS\n"
          << std::setprecision(10);
      for (const auto &row : all)
      {
        out << int(row[0]) << ',' << int(row[1]);
        for (unsigned int c = 2; c < 11; ++c)
          out << ',' << row[c];
        out << ',' << int(row[11]) << '\n';
      }
    }
    std::rename(temporary.c_str(), filename.c_str());
  }



  template <int dim>
  void
  ContactHandler<dim>::nodal_fields(
    const std::vector<types::global_dof_index> &vertex_to_dof,
    std::array<dealii::Vector<double>, 4>      &scalars,
    dealii::Vector<double>                     &shear) const
  {
    // One physical value per node, also where a node is a slave of several
    // pairs (two slave surfaces sharing an edge, two masters): CPRESS,
    // CSHEAR and CSLIP are means over the pairs weighted by the node's
    // tributary area in each (CPRESS is the node's total normal force over
    // its total area); CPRESS and CSHEAR over the pairs that hold it
    // closed, CSLIP over all (slip history outlives contact). CSTATUS is
    // the status in the pair with the largest normal force, COPEN the
    // smallest gap.
    struct NodeValues
    {
      double       closed_area = 0, area = 0, pressure = 0, slip = 0;
      double       largest_force = -1, gap = 0;
      bool         has_gap = false;
      int          status  = int(ContactStatus::open);
      Vec3<double> shear{{0, 0, 0}};
      const std::array<types::global_dof_index, dim> *dofs = nullptr;
    };
    std::map<unsigned int, NodeValues> per_vertex;
    for (const auto &pair : pairs)
      for (unsigned int k = 0; k < pair.owned.size(); ++k)
      {
        if (!pair.owned[k])
          continue;
        const auto &node = pair.slave->nodes()[k];
        const auto &r    = pair.results[k];
        NodeValues &v    = per_vertex[node.vertex];
        v.dofs           = &node.dofs;
        // Excluded nodes (area 0) still report their slip with weight 1.
        const double area = pair.area[k] > 0 ? pair.area[k] : 1e-300;
        v.area += area;
        v.slip += area * pair.history[k].slip;
        if (std::isfinite(r.gap) && (!v.has_gap || r.gap < v.gap))
        {
          v.gap     = r.gap;
          v.has_gap = true;
        }
        if (r.status == ContactStatus::open)
          continue;
        v.closed_area += area;
        v.pressure += area * r.pressure;
        for (unsigned int d = 0; d < dim; ++d)
          v.shear[d] -= area * r.traction[d];
        if (area * r.pressure > v.largest_force)
        {
          v.largest_force = area * r.pressure;
          v.status        = int(r.status);
        }
      }
    for (const auto &[vertex, v] : per_vertex)
    {
      const auto dof = vertex_to_dof[vertex];
      scalars[1][dof] += v.has_gap ? v.gap : 0.;
      scalars[2][dof] += v.slip / v.area;
      scalars[3][dof] += v.status;
      if (v.closed_area > 0)
      {
        scalars[0][dof] += v.pressure / v.closed_area;
        for (unsigned int d = 0; d < dim; ++d)
          shear[(*v.dofs)[d]] += v.shear[d] / v.closed_area;
      }
    }
    for (auto &v : scalars)
      Utilities::MPI::sum(v, mpi_communicator, v);
    Utilities::MPI::sum(shear, mpi_communicator, shear);
  }

  template class ContactHandler<2>;
  template class ContactHandler<3>;
} // namespace tribos
