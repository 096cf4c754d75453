#include <tribos/core/error_indicator.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/numerics/error_estimator.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace tribos
{
  namespace
  {
    /** Per pair and slave node: pressure, gap and whether closed, from the
     * process that owns the node (every process gets all of them). */
    template <int dim>
    std::vector<std::array<double, 3>>
    node_values(const ContactPair<dim> &pair, const MPI_Comm communicator)
    {
      std::vector<std::array<double, 4>> mine;
      for (unsigned int k = 0; k < pair.n_nodes(); ++k)
        if (pair.owned[k])
        {
          const auto  &state = pair.current[k];
          const double gap   = std::isfinite(state.distance) ?
                                 state.distance :
                                 std::numeric_limits<double>::max();
          mine.push_back({{static_cast<double>(k),
                           state.closed() ? state.result.pressure : 0.,
                           state.closed() ? state.result.gap : gap,
                           state.closed() ? 1. : 0.}});
        }
      std::vector<std::array<double, 3>> values(
        pair.n_nodes(),
        {{0, std::numeric_limits<double>::max(), 0}});
      for (const auto &part : Utilities::MPI::all_gather(communicator, mine))
        for (const auto &v : part)
          values[static_cast<unsigned int>(v[0])] = {{v[1], v[2], v[3]}};
      return values;
    }
  } // namespace



  template <int dim>
  dealii::Vector<float>
  error_indicator(const Parameters::Adaptivity        &parameters,
                  const Model<dim>                    &model,
                  const TrilinosWrappers::MPI::Vector &displacement,
                  const MaterialState<dim>            &materials,
                  const ContactHandler<dim>           *contact)
  {
    const auto    &tria         = model.triangulation();
    const MPI_Comm communicator = model.communicator();
    const auto     scaled = [&](dealii::Vector<float> &eta, const double floor)
    {
      const double largest =
        std::max<double>(Utilities::MPI::max(eta.linfty_norm(), communicator),
                         floor);
      if (largest > 0)
        eta /= largest;
    };

    dealii::Vector<float> bulk(tria.n_active_cells());
    if (parameters.kelly)
    {
      KellyErrorEstimator<dim>::estimate(model.mapping(),
                                         model.dof_handler(),
                                         model.face_quadrature(),
                                         {},
                                         displacement,
                                         bulk,
                                         ComponentMask(),
                                         nullptr,
                                         numbers::invalid_unsigned_int,
                                         tria.locally_owned_subdomain());
      // Scaled to its largest value, but not above round-off: a body that
      // moves as a rigid one (a punch before it touches) has jumps of the
      // solver's round-off only, which must not decide the refinement (they
      // did: two runs whose Newton paths differed refined other cells
      // before any contact). The floor is a strain jump of 1e-10 times the
      // largest Young's modulus over the model (Kelly's value scales with
      // the root of a volume).
      double volume = 0, e_max = 0;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          const double e = materials.youngs_modulus(cell->material_id());
          bulk[cell->active_cell_index()] *= e;
          volume += cell->measure();
          e_max = std::max(e_max, e);
        }
      volume = Utilities::MPI::sum(volume, communicator);
      e_max  = Utilities::MPI::max(e_max, communicator);
      scaled(bulk, 1e-10 * e_max * std::sqrt(volume));
    }

    // The contact indicator per cell (by CellId: a master face's cell may
    // be another process's).
    std::map<CellId, float> per_cell;
    if (contact != nullptr && parameters.contact_weight > 0)
      for (const auto &pair : contact->pairs())
      {
        const auto  values  = node_values(pair, communicator);
        const auto &surface = *pair.slave;
        double      p_max   = 0;
        for (const auto &v : values)
          p_max = std::max(p_max, std::abs(v[0]));
        std::vector<float> at_node(pair.n_nodes(), 0);
        for (const auto &face : surface.faces())
        {
          double       p_low  = std::numeric_limits<double>::max();
          double       p_high = -p_low, size = 0;
          unsigned int n_closed = 0;
          bool         closing  = false;
          for (unsigned int i = 0; i < face.n_nodes(); ++i)
          {
            const auto &v = values[face.node(i)];
            p_low         = std::min(p_low, v[0]);
            p_high        = std::max(p_high, v[0]);
            n_closed += v[2] > 0 ? 1 : 0;
            size = std::max(size, surface.nodes()[face.node(i)].size);
          }
          for (unsigned int i = 0; i < face.n_nodes(); ++i)
          {
            const auto &v = values[face.node(i)];
            if (v[2] == 0 && v[1] < parameters.closing_gap_factor * size)
              closing = true;
          }
          const float eta =
            (p_max > 0 ? (p_high - p_low) / p_max : 0.) +
            (n_closed > 0 && n_closed < face.n_nodes() ? 1. : 0.) +
            (closing ? 1. : 0.);
          auto &cell = per_cell[CellId(face.cell)];
          cell       = std::max(cell, eta);
          for (unsigned int i = 0; i < face.n_nodes(); ++i)
            at_node[face.node(i)] = std::max(at_node[face.node(i)], eta);
        }
        // The master faces the owned nodes are paired with.
        if (pair.master)
        {
          std::vector<std::pair<CellId::binary_type, float>> mine;
          for (unsigned int k = 0; k < pair.n_nodes(); ++k)
            if (pair.owned[k] && pair.current[k].paired &&
                pair.current[k].face >= 0 && at_node[k] > 0)
              mine.emplace_back(pair.master->faces()[pair.current[k].face].cell,
                                at_node[k]);
          for (const auto &part :
               Utilities::MPI::all_gather(communicator, mine))
            for (const auto &[id, eta] : part)
            {
              auto &cell = per_cell[CellId(id)];
              cell       = std::max(cell, eta);
            }
        }
      }
    dealii::Vector<float> on_contact(tria.n_active_cells());
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        const auto found = per_cell.find(cell->id());
        if (found != per_cell.end())
          on_contact[cell->active_cell_index()] = found->second;
      }
    scaled(on_contact, 0.);

    const double          a = parameters.kelly ? parameters.contact_weight : 1;
    dealii::Vector<float> eta(tria.n_active_cells());
    for (unsigned int i = 0; i < eta.size(); ++i)
      eta[i] = (1 - a) * bulk[i] + a * on_contact[i];
    return eta;
  }



  template <int dim>
  ContactZone<dim>
  contact_zone(const Model<dim> &model, const ContactHandler<dim> &contact)
  {
    const auto    &tria         = model.triangulation();
    const MPI_Comm communicator = model.communicator();
    // (cell, face size, 0 slave / 1 master) of the zone's faces.
    std::vector<std::tuple<CellId::binary_type, double, int>> mine;
    const auto face_size = [](const ContactSurface<dim>                &surface,
                              const typename ContactSurface<dim>::Face &face)
    {
      double size = 0;
      for (unsigned int i = 0; i < face.n_nodes(); ++i)
        size = std::max(size, surface.nodes()[face.node(i)].size);
      return size;
    };
    ContactZone<dim> zone;
    for (const auto &pair : contact.pairs())
    {
      const auto values = node_values(pair, communicator);
      // The box of the closed nodes (every process knows every node).
      std::vector<Point<dim>> closed;
      for (unsigned int k = 0; k < pair.n_nodes(); ++k)
        if (values[k][2] > 0)
        {
          Point<dim> x;
          for (unsigned int d = 0; d < dim; ++d)
            x[d] = pair.slave->nodes()[k].reference[d];
          closed.push_back(x);
        }
      if (!closed.empty())
        zone.boxes.emplace_back(closed);
      const unsigned int me = Utilities::MPI::this_mpi_process(communicator);
      for (const auto &face : pair.slave->faces())
        if (face.owner == me)
          for (unsigned int i = 0; i < face.n_nodes(); ++i)
            if (values[face.node(i)][2] > 0)
            {
              mine.emplace_back(face.cell, face_size(*pair.slave, face), 0);
              break;
            }
      if (pair.master)
        for (unsigned int k = 0; k < pair.n_nodes(); ++k)
          if (pair.owned[k] && pair.current[k].closed() &&
              pair.current[k].paired && pair.current[k].face >= 0)
          {
            const auto &face = pair.master->faces()[pair.current[k].face];
            mine.emplace_back(face.cell, face_size(*pair.master, face), 1);
          }
    }
    std::map<CellId, std::array<double, 2>> cells;
    for (const auto &part : Utilities::MPI::all_gather(communicator, mine))
      for (const auto &[id, size, side] : part)
      {
        auto &sizes =
          cells.try_emplace(CellId(id), std::array<double, 2>{}).first->second;
        sizes[side] = std::max(sizes[side], size);
      }
    zone.slave_size.reinit(tria.n_active_cells());
    zone.master_size.reinit(tria.n_active_cells());
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        const auto found = cells.find(cell->id());
        if (found != cells.end())
        {
          zone.slave_size[cell->active_cell_index()]  = found->second[0];
          zone.master_size[cell->active_cell_index()] = found->second[1];
        }
      }
    return zone;
  }



  template <int dim>
  unsigned int
  n_faces_closed_below_level(const ContactHandler<dim> &contact,
                             const unsigned int         maximum_level,
                             const MPI_Comm             communicator)
  {
    unsigned int n_faces = 0;
    for (const auto &pair : contact.pairs())
    {
      // Per owned node whether the increment closed it, known everywhere
      // (a face's nodes may be owned by several processes).
      // The master faces they closed on count too (a node-to-segment
      // contact is as fine as its master).
      std::vector<unsigned int> mine;
      for (unsigned int k = 0; k < pair.n_nodes(); ++k)
        if (pair.owned[k] && pair.current[k].closed() &&
            !pair.committed[k].closed())
        {
          mine.push_back(k);
          const int face = pair.current[k].face;
          if (pair.master && pair.current[k].paired && face >= 0 &&
              CellId(pair.master->faces()[face].cell)
                  .get_child_indices()
                  .size() < maximum_level)
            ++n_faces;
        }
      std::vector<char> closed(pair.n_nodes(), 0);
      for (const auto &part : Utilities::MPI::all_gather(communicator, mine))
        for (const auto k : part)
          closed[k] = 1;
      // Every process counts the faces of its own cells.
      const unsigned int me = Utilities::MPI::this_mpi_process(communicator);
      for (const auto &face : pair.slave->faces())
      {
        const CellId cell(face.cell);
        if (cell.get_child_indices().size() >= maximum_level)
          continue;
        bool any = false;
        for (unsigned int i = 0; i < face.n_nodes(); ++i)
          any = any || closed[face.node(i)] != 0;
        if (any && face.owner == me)
          ++n_faces;
      }
    }
    return Utilities::MPI::sum(n_faces, communicator);
  }



  template unsigned int
  n_faces_closed_below_level<2>(const ContactHandler<2> &,
                                const unsigned int,
                                const MPI_Comm);
  template unsigned int
  n_faces_closed_below_level<3>(const ContactHandler<3> &,
                                const unsigned int,
                                const MPI_Comm);
  template ContactZone<2>
  contact_zone<2>(const Model<2> &, const ContactHandler<2> &);
  template ContactZone<3>
  contact_zone<3>(const Model<3> &, const ContactHandler<3> &);
  template dealii::Vector<float>
  error_indicator<2>(const Parameters::Adaptivity &,
                     const Model<2> &,
                     const TrilinosWrappers::MPI::Vector &,
                     const MaterialState<2> &,
                     const ContactHandler<2> *);
  template dealii::Vector<float>
  error_indicator<3>(const Parameters::Adaptivity &,
                     const Model<3> &,
                     const TrilinosWrappers::MPI::Vector &,
                     const MaterialState<3> &,
                     const ContactHandler<3> *);
} // namespace tribos
