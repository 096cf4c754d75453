#include <tribos/base/exceptions.h>
#include <tribos/contact/search/self_contact_search.h>

#include <array>
#include <cmath>
#include <string>

namespace tribos
{
  template <int dim>
  void
  SelfContactSearch<dim>::initialize(const ContactPair<dim> &pair,
                                     const double            search_distance)
  {
    neighbourhood.clear();
    warning.clear();
    if (pair.master != pair.slave)
      return;
    const auto &nodes = pair.slave->nodes();
    const auto &faces = pair.slave->faces();
    double      size  = 0;
    neighbourhood.resize(nodes.size());
    for (unsigned int k = 0; k < nodes.size(); ++k)
    {
      auto &near = neighbourhood[k];
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
    for (const auto &near : neighbourhood)
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
    reach   = 2 * size;
    largest = std::min(search_distance, 2 * extent);
    if (std::isfinite(search_distance))
      check_reach(pair, search_distance);
  }



  template <int dim>
  void
  SelfContactSearch<dim>::check_reach(const ContactPair<dim> &pair,
                                      const double            distance)
  {
    const auto &nodes = pair.slave->nodes();
    const auto &faces = pair.slave->faces();
    // Face f's projection of x (its vertices' linear face), with the unit
    // normal and the point there, in the reference configuration.
    const auto project = [&](const unsigned int  f,
                             const Vec3<double> &x,
                             Vec3<double>       &normal,
                             Vec3<double>       &point)
    {
      Vec3<double> y[4];
      for (unsigned int v = 0; v < faces[f].n_vertices; ++v)
        y[v] = nodes[faces[f].nodes[v]].reference;
      return pair.slave->shape().template visit<dim>(
        [&](auto kind)
        {
          using Linear       = typename decltype(kind)::Linear;
          const Projection p = Linear::project(x, y, true);
          Vec3<double>     tangents[2];
          Linear::geometry(y, p.xi, point, tangents, normal);
          return p.distance;
        });
    };
    // The faces' boxes, widened by the search distance.
    std::vector<std::array<double, 2 * dim>> boxes(faces.size());
    for (unsigned int f = 0; f < faces.size(); ++f)
      for (unsigned int d = 0; d < dim; ++d)
      {
        double lo = nodes[faces[f].nodes[0]].reference[d], hi = lo;
        for (unsigned int v = 1; v < faces[f].n_vertices; ++v)
        {
          lo = std::min(lo, nodes[faces[f].nodes[v]].reference[d]);
          hi = std::max(hi, nodes[faces[f].nodes[v]].reference[d]);
        }
        boxes[f][d]       = lo - distance;
        boxes[f][dim + d] = hi + distance;
      }
    // Does any node face a face of the surface, in front of it, within
    // the search distance?
    for (unsigned int k = 0; k < nodes.size(); ++k)
    {
      const Vec3<double> &x = nodes[k].reference;
      Vec3<double>        n_k{{0, 0, 0}}, n, point;
      for (const unsigned int f : nodes[k].faces)
      {
        project(f, x, n, point);
        n_k = n_k + n;
      }
      n_k = scale(1. / std::max(norm(n_k), 1e-300), n_k);
      for (unsigned int f = 0; f < faces.size(); ++f)
      {
        bool beyond = false;
        for (unsigned int d = 0; d < dim; ++d)
          beyond = beyond || x[d] < boxes[f][d] || x[d] > boxes[f][dim + d];
        if (beyond || own(k, f))
          continue;
        if (project(f, x, n, point) <= distance && dot(n_k, n) < -0.5 &&
            dot(x - point, n) >= 0)
          return;
      }
    }
    warning = "the self-contact pair <" + pair.description.text +
              ">: no node of its surface faces a face of it within "
              "Contact/Search distance = " +
              to_scientific(distance) +
              " (the reference configuration); the surface touches "
              "itself only where it folds closer than that.";
  }



  template class SelfContactSearch<2>;
  template class SelfContactSearch<3>;
} // namespace tribos
