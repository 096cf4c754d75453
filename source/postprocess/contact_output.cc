#include <tribos/base/write_atomically.h>
#include <tribos/postprocess/contact_output.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>

namespace tribos
{
  template <int dim>
  ContactOutput<dim>::ContactOutput(const ContactHandler<dim> &contact)
    : contact(contact)
  {
  }



  template <int dim>
  ContactStatistics
  ContactOutput<dim>::statistics() const
  {
    ContactStatistics s;
    for (const auto &pair : contact.pairs())
    {
      std::array<double, 5> forces = {{0, 0, 0, 0, 0}};
      for (unsigned int k = 0; k < pair.n_nodes(); ++k)
      {
        const auto &r = pair.current[k].result;
        if (!pair.owned[k] || r.status == ContactStatus::open)
          continue;
        const double area = r.area;
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
        f = Utilities::MPI::sum(f, contact.communicator());
      s.pair_forces.push_back(forces);
    }
    s.max_penetration =
      Utilities::MPI::max(s.max_penetration, contact.communicator());
    s.n_active = Utilities::MPI::sum(s.n_active, contact.communicator());
    s.n_stick  = Utilities::MPI::sum(s.n_stick, contact.communicator());
    s.n_slip   = Utilities::MPI::sum(s.n_slip, contact.communicator());
    return s;
  }



  template <int dim>
  std::vector<std::string>
  ContactOutput<dim>::column_names() const
  {
    std::vector<std::string> names;
    const char              *axis = "xyz";
    for (unsigned int p = 0; p < contact.pairs().size(); ++p)
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
  ContactOutput<dim>::columns() const
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
  std::vector<std::vector<NodeState>>
  ContactOutput<dim>::reported_states() const
  {
    std::vector<std::vector<NodeState>> states;
    // Each process sends, for the parents it owns, one row per hanging
    // node they carry: pair, hanging node, weight, pressure, traction (3),
    // gap, slip, status. ContactPair::carried is the same on all
    // processes, so all take part or none.
    constexpr unsigned int n_columns = 10;
    std::vector<double>    rows;
    bool                   any_hanging = false;
    for (unsigned int p = 0; p < contact.pairs().size(); ++p)
    {
      const auto &pair = contact.pairs()[p];
      states.push_back(pair.current);
      for (unsigned int k = 0; k < pair.n_nodes(); ++k)
        for (const auto &[h, weight] : pair.carried[k])
        {
          any_hanging = true;
          if (!pair.owned[k])
            continue;
          const auto  &s                 = pair.current[k];
          const auto  &r                 = s.result;
          const double values[n_columns] = {double(p),
                                            double(h),
                                            weight,
                                            r.pressure,
                                            r.traction[0],
                                            r.traction[1],
                                            r.traction[2],
                                            r.gap,
                                            s.slip,
                                            double(int(r.status))};
          rows.insert(rows.end(), values, values + n_columns);
        }
    }
    if (!any_hanging)
      return states;

    // The hanging nodes' values are sums over their parents.
    std::vector<std::vector<double>> largest_force(states.size());
    for (unsigned int p = 0; p < states.size(); ++p)
    {
      largest_force[p].assign(states[p].size(), -1);
      for (const auto &carried : contact.pairs()[p].carried)
        for (const auto &entry : carried)
        {
          auto &s  = states[p][entry.first];
          s.result = ContactPointResult();
          s.slip   = 0;
        }
    }
    for (const auto &part :
         Utilities::MPI::all_gather(contact.communicator(), rows))
      for (unsigned int i = 0; i < part.size(); i += n_columns)
      {
        const double      *row  = &part[i];
        const unsigned int p    = row[0];
        const unsigned int h    = row[1];
        const double       w    = row[2];
        const auto        &pair = contact.pairs()[p];
        if (!pair.owned[h])
          continue;
        auto &r = states[p][h].result;
        r.pressure += w * row[3];
        for (unsigned int d = 0; d < 3; ++d)
          r.traction[d] += w * row[4 + d];
        r.gap += w * row[7];
        states[p][h].slip += w * row[8];
        const auto status = ContactStatus(int(row[9]));
        if (status != ContactStatus::open && w * row[3] > largest_force[p][h])
        {
          largest_force[p][h] = w * row[3];
          r.status            = status;
        }
      }
    return states;
  }



  template <int dim>
  void
  ContactOutput<dim>::write_csv(const std::string &filename) const
  {
    // One row per slave node: pair, body, x, y, z, CPRESS, CSHEAR (3),
    // COPEN, CSLIP, CSTATUS, X, Y, Z (the reference position: theories
    // such as Hertz's are written in it), and the node's number (sorting).
    constexpr unsigned int n_columns = 16;
    std::vector<double>    rows;
    const auto             states = reported_states();
    for (unsigned int p = 0; p < contact.pairs().size(); ++p)
    {
      const auto &pair = contact.pairs()[p];
      for (unsigned int k = 0; k < pair.n_nodes(); ++k)
      {
        if (!pair.owned[k])
          continue;
        const auto  &r    = states[p][k].result;
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
                                          states[p][k].slip,
                                          double(int(r.status)),
                                          node.reference[0],
                                          node.reference[1],
                                          node.reference[2],
                                          double(k)};
        rows.insert(rows.end(), values, values + n_columns);
      }
    }
    const auto gathered =
      Utilities::MPI::gather(contact.communicator(), rows, 0);
    if (Utilities::MPI::this_mpi_process(contact.communicator()) != 0)
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
              { return a[0] != b[0] ? a[0] < b[0] : a[15] < b[15]; });

    write_atomically(
      filename,
      [&](std::ostream &out)
      {
        out << "pair,body,x,y,z,CPRESS,CSHEAR_x,CSHEAR_y,CSHEAR_z,COPEN,CSLIP,"
               "CSTATUS,X,Y,Z\n"
            << std::setprecision(15);
        for (const auto &row : all)
        {
          out << int(row[0]) << ',' << int(row[1]);
          for (unsigned int c = 2; c < 11; ++c)
            out << ',' << row[c];
          out << ',' << int(row[11]);
          for (unsigned int c = 12; c < 15; ++c)
            out << ',' << row[c];
          out << '\n';
        }
      });
  }



  template <int dim>
  void
  ContactOutput<dim>::nodal_fields(
    const std::map<types::global_dof_index, types::global_dof_index>
                                                 &scalar_dof,
    std::array<TrilinosWrappers::MPI::Vector, 4> &scalars,
    TrilinosWrappers::MPI::Vector                &shear) const
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
    std::map<types::global_dof_index, NodeValues> per_node;
    const auto                                    states = reported_states();
    for (unsigned int p = 0; p < contact.pairs().size(); ++p)
      for (unsigned int k = 0; k < contact.pairs()[p].n_nodes(); ++k)
      {
        const auto &pair = contact.pairs()[p];
        if (!pair.owned[k])
          continue;
        const auto &node = pair.slave->nodes()[k];
        const auto &r    = states[p][k].result;
        NodeValues &v    = per_node[node.dofs[0]];
        v.dofs           = &node.dofs;
        // Excluded nodes (area 0) still report their slip with weight 1.
        const double area = pair.area[k] > 0 ? pair.area[k] : 1e-300;
        v.area += area;
        v.slip += area * states[p][k].slip;
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
    for (const auto &[first_dof, v] : per_node)
    {
      const auto dof = scalar_dof.at(first_dof);
      // A slave node beyond the search distance has no gap: nan, not 0
      // (which would read as touching).
      scalars[1][dof] =
        v.has_gap ? v.gap : std::numeric_limits<double>::quiet_NaN();
      scalars[2][dof] = v.slip / v.area;
      scalars[3][dof] = v.status;
      if (v.closed_area > 0)
      {
        scalars[0][dof] = v.pressure / v.closed_area;
        for (unsigned int d = 0; d < dim; ++d)
          shear[(*v.dofs)[d]] = v.shear[d] / v.closed_area;
      }
    }
    for (auto &v : scalars)
      v.compress(VectorOperation::insert);
    shear.compress(VectorOperation::insert);
  }

  template class ContactOutput<2>;
  template class ContactOutput<3>;
} // namespace tribos
