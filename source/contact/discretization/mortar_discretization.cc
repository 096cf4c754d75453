#include <tribos/base/exceptions.h>
#include <tribos/contact/contact_pair.h>
#include <tribos/contact/discretization/mortar_discretization.h>

#include <algorithm>
#include <cmath>

namespace tribos
{
  namespace
  {
    /** Append to @p into the entries of @p from that it does not hold. */
    void
    append_missing(std::vector<unsigned int>       &into,
                   const std::vector<unsigned int> &from)
    {
      for (const unsigned int i : from)
        if (std::find(into.begin(), into.end(), i) == into.end())
          into.push_back(i);
    }
  } // namespace



  template <int dim>
  MortarDiscretization<dim>::MortarDiscretization(
    const Parameters::Contact &parameters,
    const bool                 dual,
    const bool                 smoothed_master,
    const bool                 axisymmetric)
    : parameters(parameters)
    , dual(dual)
    , smoothed_master(smoothed_master)
    , axisymmetric(axisymmetric)
  {
  }



  template <int dim>
  std::string
  MortarDiscretization<dim>::name() const
  {
    return std::string("mortar, ") + (dual ? "dual" : "standard") + " basis" +
           (smoothed_master ? ", master's averaged normals" : "");
  }



  template <int dim>
  void
  MortarDiscretization<dim>::initialize(const ContactPair<dim> &pair)
  {
    const unsigned int n_slaves = pair.n_nodes();
    faces_of_node.assign(n_slaves, {});
    self_search.initialize(pair, parameters.search_distance);
    // The standard quadratic functions of the vertex on the axis
    // integrate to zero against 2 pi r: that node carries no multiplier,
    // the others then miss a partition of unity and Newton does not
    // converge even on the patch test. The dual basis has no such node.
    // A hanging node of a nine-node face hangs on up to nine parents with
    // weights of both signs; the parents' carried functions are written
    // for the bilinear faces of Q1 (at most four per face).
    if (pair.slave->quadratic_quadrilaterals())
      for (const auto &carried : pair.carried)
        AssertThrow(carried.empty(),
                    ExcMessage("Contact pair <" + pair.description.text +
                               ">: mortar contact on the nine-node faces "
                               "of Q2 hexahedra needs a slave surface "
                               "without hanging nodes, which local "
                               "refinement makes: set the scene's local "
                               "refinements to 0 (Scene/Refinement refines "
                               "uniformly), or make the other body the "
                               "slave."));
    AssertThrow(!pair.slave->quadratic() || !axisymmetric || dual,
                ExcMessage("Contact pair <" + pair.description.text +
                           ">: Contact/Mortar basis = standard is not "
                           "available with Polynomial degree = 2 and "
                           "Axisymmetric = true; use Mortar basis = dual."));
    // A hanging node's multiplier function goes to its parents (3D Q1
    // elements only: a 2D surface has no hanging nodes, Q2 contact is
    // 2D); a node shared with another pair has no parents to take it.
    std::vector<bool> is_carried(n_slaves, false);
    for (unsigned int k = 0; k < n_slaves; ++k)
      for (const auto &[h, weight] : pair.carried[k])
        is_carried[h] = !pair.excluded[k];
    for (unsigned int k = 0; k < n_slaves; ++k)
    {
      if (!pair.excluded[k] || (dim == 3 && is_carried[k]))
        continue;
      std::string at;
      for (unsigned int d = 0; d < dim; ++d)
        at += (d > 0 ? ", " : "") +
              std::to_string(pair.slave->nodes()[k].reference[d]);
      AssertThrow(false,
                  ExcMessage("Contact pair <" + pair.description.text +
                             ">: mortar with multipliers needs every slave "
                             "node to carry its own multiplier or to hang "
                             "on nodes that carry it; the slave node at (" +
                             at +
                             ") is shared with another pair's slave "
                             "surface. Write both surfaces as one slave "
                             "('3, 4 : 5'), or use node to segment."));
    }
  }



  template <int dim>
  void
  MortarDiscretization<dim>::slave_stencil(
    const ContactPair<dim>    &pair,
    const unsigned int         k,
    std::vector<unsigned int> &nodes) const
  {
    nodes.assign(1, k);
    for (const unsigned int f : pair.slave->nodes()[k].faces)
      for (unsigned int i = 0; i < pair.slave->faces()[f].n_nodes(); ++i)
      {
        const unsigned int m = pair.slave->faces()[f].node(i);
        if (std::find(nodes.begin(), nodes.end(), m) == nodes.end())
          nodes.push_back(m);
      }
  }



  template <int dim>
  void
  MortarDiscretization<dim>::stencil(const ContactPair<dim>    &pair,
                                     const unsigned int         k,
                                     std::vector<unsigned int> &nodes) const
  {
    slave_stencil(pair, k, nodes);
    std::vector<unsigned int> other;
    for (const auto &[h, weight] : pair.carried[k])
    {
      slave_stencil(pair, h, other);
      append_missing(nodes, other);
    }
  }



  template <int dim>
  void
  MortarDiscretization<dim>::element_slave_faces(
    const ContactPair<dim>    &pair,
    const unsigned int         k,
    std::vector<unsigned int> &faces) const
  {
    faces = pair.slave->nodes()[k].faces;
    for (const auto &[h, weight] : pair.carried[k])
      append_missing(faces, pair.slave->nodes()[h].faces);
  }



  template <int dim>
  void
  MortarDiscretization<dim>::element_master_faces(
    const ContactPair<dim>    &pair,
    const unsigned int         k,
    std::vector<unsigned int> &faces) const
  {
    faces = faces_of_node[k];
    for (const auto &[h, weight] : pair.carried[k])
      append_missing(faces, faces_of_node[h]);
  }



  template <int dim>
  double
  MortarDiscretization<dim>::exchange_reach(const ContactPair<dim> &pair,
                                            const unsigned int      k) const
  {
    // A mortar element integrates every master face that overlaps its
    // slave faces and faces them, however far, once one is within the
    // search distance: over a slave face of size L (Q2: plus a quarter), a
    // master that rises at up to 75 degrees over it (the steepest it
    // takes, tan 75 = 3.7) stays within 3.7 * 1.25 L < 5 L of the closest
    // face.
    double reach = 0;
    for (const unsigned int f : pair.slave->nodes()[k].faces)
      for (unsigned int i = 0; i < pair.slave->faces()[f].n_nodes(); ++i)
      {
        const unsigned int m = pair.slave->faces()[f].node(i);
        if (std::binary_search(pair.read_slave_nodes.begin(),
                               pair.read_slave_nodes.end(),
                               m))
          reach = std::max(reach,
                           5 * norm(pair.slave_positions[k] -
                                    pair.slave_positions[m]));
      }
    return reach;
  }



  template <int dim>
  void
  MortarDiscretization<dim>::add_couplings(
    const ContactPair<dim>          &pair,
    const AffineConstraints<double> &constraints,
    DynamicSparsityPattern          &dsp) const
  {
    // A mortar element couples all the master faces of its node with each
    // other: one element per node over the union of its faces.
    std::vector<types::global_dof_index> dofs;
    for (auto c = pair.couplings.begin(); c != pair.couplings.end();)
    {
      const unsigned int k = c->first;
      element_dofs(pair, k, -1, dofs);
      for (; c != pair.couplings.end() && c->first == k; ++c)
      {
        const auto &face = pair.master->faces()[c->second];
        for (unsigned int i = 0; i < face.n_nodes(); ++i)
          for (const auto dof : pair.master->nodes()[face.node(i)].dofs)
            dofs.push_back(dof);
      }
      std::sort(dofs.begin(), dofs.end());
      dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
      constraints.add_entries_local_to_global(dofs, dsp, false);
    }
  }



  template <int dim>
  void
  MortarDiscretization<dim>::used_couplings(
    const ContactPair<dim>                          &pair,
    const unsigned int                               k,
    std::set<std::pair<unsigned int, unsigned int>> &into) const
  {
    std::vector<unsigned int> faces;
    element_master_faces(pair, k, faces);
    for (const unsigned int f : faces)
      this->insert_couplings(pair, k, f, into);
  }



  template <int dim>
  void
  MortarDiscretization<dim>::element_dofs(
    const ContactPair<dim>               &pair,
    const unsigned int                    k,
    const int                             face,
    std::vector<types::global_dof_index> &dofs) const
  {
    const auto &slave_dofs = pair.slave->nodes()[k].dofs;
    dofs.assign(slave_dofs.begin(), slave_dofs.end());
    std::vector<unsigned int> nodes;
    stencil(pair, k, nodes);
    for (unsigned int i = 1; i < nodes.size(); ++i)
      for (const auto dof : pair.slave->nodes()[nodes[i]].dofs)
        dofs.push_back(dof);
    if (face >= 0)
      for (unsigned int i = 0; i < pair.master->faces()[face].n_nodes(); ++i)
        for (const auto dof :
             pair.master->nodes()[pair.master->faces()[face].node(i)].dofs)
          dofs.push_back(dof);
    pair.append_unknown_dofs(k, dofs);
  }



  template <int dim>
  void
  MortarDiscretization<dim>::begin_assembly(const ContactPair<dim> &,
                                            const double,
                                            const double)
  {
    // The positions change between assemblies.
    overlap_cache.entries.clear();
  }



  template <int dim>
  void
  MortarDiscretization<dim>::set_positions(
    const ContactPair<dim>               &pair,
    const unsigned int                    k,
    Input                                &input,
    std::vector<types::global_dof_index> &dofs) const
  {
    const auto &slave_nodes  = stencil_buffer;
    const auto &master_nodes = master_buffer;
    input.n_slave_nodes      = slave_nodes.size();
    dofs.clear();
    for (unsigned int i = 0; i < slave_nodes.size(); ++i)
    {
      input.xs[i]     = pair.slave_positions[slave_nodes[i]];
      input.xs_old[i] = pair.old_slave_positions[slave_nodes[i]];
      for (const auto dof : pair.slave->nodes()[slave_nodes[i]].dofs)
        dofs.push_back(dof);
    }
    input.n_master_nodes = master_nodes.size();
    for (unsigned int l = 0; l < master_nodes.size(); ++l)
    {
      input.xm[l]     = pair.master_positions[master_nodes[l]];
      input.xm_old[l] = pair.old_master_positions[master_nodes[l]];
      for (const auto dof : pair.master->nodes()[master_nodes[l]].dofs)
        dofs.push_back(dof);
    }
    pair.append_unknown_dofs(k, dofs);
    input.dual = dual;
    // A floor for nodes whose tributary area vanishes (Q2's vertex on
    // the axis of an axisymmetric body: int N_j 2 pi r = 0 there), which
    // carry no contact.
    const double size = pair.slave->nodes()[k].size;
    const double floor =
      1e-9 * std::pow(size, dim - 1) * (axisymmetric ? size : 1.);
    // (The node's whole area: a self pair's area_factor halves pair.area
    // but not the weight w_j.)
    input.min_weight  = 1e-3 * std::max(pair.area[k] / pair.area_factor, floor);
    input.area_factor = pair.area_factor;
  }



  template <>
  bool
  MortarDiscretization<2>::make_input(
    const ContactPair<2>                 &pair,
    const unsigned int                    k,
    MortarInput                          &input,
    std::vector<types::global_dof_index> &dofs,
    std::string                          &refusal)
  {
    auto &slave_nodes  = stencil_buffer;
    auto &master_nodes = master_buffer;
    master_nodes.clear();
    const auto local = internal::local_number;
    slave_stencil(pair, k, slave_nodes);
    // 2 nodes per segment on Q1, 3 (the ends, then the middle) on Q2.
    input.shape                        = pair.slave->shape();
    const unsigned int n_segment_nodes = input.shape.n_nodes();
    for (const unsigned int f : pair.slave->nodes()[k].faces)
    {
      auto &segment = input.slave_segment[input.n_slave_segments++];
      for (unsigned int v = 0; v < n_segment_nodes; ++v)
        segment[v] = local(slave_nodes, pair.slave->faces()[f].node(v));
    }
    // More master nodes than the element holds: refused, with the reason.
    const auto too_many = [&]()
    {
      if (master_nodes.size() <= max_mortar_master_nodes)
        return false;
      const Vec3<double> &x = pair.slave_positions[k];
      if (refusal.empty())
        refusal = "contact pair <" + pair.description.text +
                  ">: the mortar element of the slave node at (" +
                  to_scientific(x[0]) + ", " + to_scientific(x[1]) +
                  ") overlaps more than " +
                  std::to_string(max_mortar_master_nodes) +
                  " master nodes (an iterate gone astray, or a master much "
                  "finer than the slave: make the finer side the slave)";
      return true;
    };
    for (const unsigned int f : faces_of_node[k])
    {
      std::array<unsigned int, 3> segment{};
      for (unsigned int v = 0; v < n_segment_nodes; ++v)
        segment[v] = local(master_nodes, pair.master->faces()[f].node(v));
      if (too_many())
        return false;
      input.master_segment[input.n_master_segments++] = segment;
    }
    // A smoothed master: the nodes beyond each segment's ends
    // (MasterFace::beyond, as SmoothedSegment and the search's known faces
    // read them) for the averaged normals; they join the element after the
    // segments' nodes.
    input.smoothed_master = smoothed_master;
    for (unsigned int m = 0; smoothed_master && m < input.n_master_segments;
         ++m)
    {
      const auto &face = pair.master->faces()[faces_of_node[k][m]];
      for (unsigned int e = 0; e < 2; ++e)
        input.master_beyond[m][e] =
          face.beyond[e] >= 0 ?
            static_cast<int>(local(master_nodes, face.beyond[e])) :
            -1;
      if (too_many())
        return false;
    }

    set_positions(pair, k, input, dofs);
    input.axisymmetric = axisymmetric;
    return true;
  }



  template <>
  bool
  MortarDiscretization<3>::make_input(
    const ContactPair<3>                 &pair,
    const unsigned int                    k,
    MortarInput3D                        &input,
    std::vector<types::global_dof_index> &dofs,
    std::string                          &refusal)
  {
    auto &slave_nodes  = stencil_buffer;
    auto &master_nodes = master_buffer;
    master_nodes.clear();
    const auto local  = internal::local_number;
    const auto refuse = [&](const std::string &what)
    {
      const Vec3<double> &x = pair.slave_positions[k];
      if (refusal.empty())
        refusal = "contact pair <" + pair.description.text +
                  ">: the mortar element of the slave node at (" +
                  to_scientific(x[0]) + ", " + to_scientific(x[1]) + ", " +
                  to_scientific(x[2]) + ") " + what +
                  " (an iterate gone astray, or a master much finer than "
                  "the slave: make the finer side the slave)";
      return false;
    };
    // The faces of node k and of the hanging nodes it carries, each with
    // the nodes whose functions the element integrates on it.
    this->stencil(pair, k, slave_nodes);
    std::vector<unsigned int> faces;
    element_slave_faces(pair, k, faces);
    if (slave_nodes.size() > MortarInput3D::max_slave_nodes ||
        faces.size() > MortarInput3D::max_slave_faces)
      return refuse("has more than " +
                    std::to_string(MortarInput3D::max_slave_faces) +
                    " slave faces");
    for (const unsigned int f : faces)
    {
      const unsigned int i   = input.n_slave_faces++;
      input.slave_face_id[i] = f;
      input.n_carriers[i]    = 0;
      input.slave_face[i].n  = pair.slave->faces()[f].n_nodes();
      for (unsigned int v = 0; v < input.slave_face[i].n; ++v)
      {
        const unsigned int node      = pair.slave->faces()[f].node(v);
        input.slave_face[i].nodes[v] = local(slave_nodes, node);
        if (node == k)
          input.carriers[i][input.n_carriers[i]++] = {v, 1.};
        for (const auto &[h, weight] : pair.carried[k])
          if (node == h)
            input.carriers[i][input.n_carriers[i]++] = {v, weight};
      }
    }

    // The master faces of node k and of its hanging nodes.
    std::vector<unsigned int> master_faces;
    element_master_faces(pair, k, master_faces);
    if (master_faces.size() > max_mortar_master_nodes_3d)
      return refuse("overlaps more than " +
                    std::to_string(max_mortar_master_nodes_3d) +
                    " master faces");
    for (const unsigned int f : master_faces)
    {
      MortarFace3D face;
      face.n = pair.master->faces()[f].n_nodes();
      for (unsigned int v = 0; v < face.n; ++v)
        face.nodes[v] = local(master_nodes, pair.master->faces()[f].node(v));
      if (master_nodes.size() > max_mortar_master_nodes_3d)
        return refuse("overlaps more than " +
                      std::to_string(max_mortar_master_nodes_3d) +
                      " master nodes");
      input.master_face_id[input.n_master_faces] = f;
      input.master_face[input.n_master_faces++]  = face;
    }
    // The AD number holds the coordinates of every node and the unknowns.
    const unsigned int n_derivatives =
      3 * (slave_nodes.size() + master_nodes.size()) +
      pair.enforcement->n_node_unknowns();
    if (n_derivatives > max_contact_derivatives)
      return refuse("couples " + std::to_string(n_derivatives) +
                    " unknowns, more than the " +
                    std::to_string(max_contact_derivatives) +
                    " its derivatives hold");

    set_positions(pair, k, input, dofs);
    input.cache = &overlap_cache;
    return true;
  }



  template <int dim>
  ElementOutcome
  MortarDiscretization<dim>::evaluate(
    ContactPair<dim>                     &pair,
    const unsigned int                    k,
    const SlaveInput                     &slave,
    double                               *R,
    double                               *K,
    std::vector<types::global_dof_index> &dofs,
    std::string                          &refusal)
  {
    // The node's element over its slave segments (its weight may still
    // leave it without a master).
    using Element = std::conditional_t<dim == 2, Mortar2D, Mortar3D>;
    Input input;
    if (!make_input(pair, k, input, dofs, refusal))
      return {ElementOutcome::Kind::refused, false};
    bool         paired = false;
    Vec3<double> point;
    NodeState   &state = pair.current[k];
    state.result =
      Element::evaluate(slave, input, *pair.enforcement, R, K, paired, point);
    if (!paired)
      return {ElementOutcome::Kind::unpaired, false};
    state.point = point;
    return {ElementOutcome::Kind::element, true};
  }



  template class MortarDiscretization<2>;
  template class MortarDiscretization<3>;
} // namespace tribos
