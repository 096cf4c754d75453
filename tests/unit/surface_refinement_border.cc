// ctest: labels quick
/**
 * Unit test of a master surface across a refinement border (hanging nodes,
 * as an adapted mesh has them): the top of a 2 x 2 x 1 box of hexahedra
 * with one cell refined once, 4 fine and 3 coarse faces. A face edge
 * continues into the next face (ContactSurface::Face::continues: node to
 * segment treats a projection clamped at an edge that does not continue as
 * the end of the master) everywhere but on the square's outer border. Where
 * the fine faces meet the coarse ones no face holds both nodes of an edge
 * (a coarse edge's middle is a hanging node of the fine faces): before
 * ContactSurface::continues_across_refinement() those 6 edges (4 fine, 2
 * coarse) ended the surface. Also: the same with the other cell refined
 * twice (fine, finer and coarse faces at one node).
 */

#include <tribos/contact/surface/contact_surface.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <iostream>

using namespace dealii;
using namespace tribos;

namespace
{
  /** The faces' edges that continue where they should not, or do not
   * where they should, on the top (boundary 5) of @p tria. */
  unsigned int
  wrong_edges(const Triangulation<3> &tria, const std::string &name)
  {
    const FESystem<3> fe(FE_Q<3>(1), 3);
    DoFHandler<3>     dofs(tria);
    dofs.distribute_dofs(fe);
    const ContactSurface<3> surface(dofs, {5});
    // The edges of the lexicographic quadrilateral 0 1 / 2 3 per local
    // coordinate and side (MasterFace<3>).
    const unsigned int edge[2][2][2] = {{{0, 2}, {1, 3}}, {{0, 1}, {2, 3}}};
    unsigned int       n_wrong = 0, n_edges = 0, n_border = 0;
    for (const auto &face : surface.faces())
      for (unsigned int c = 0; c < 2; ++c)
        for (unsigned int side = 0; side < 2; ++side)
        {
          const auto &a         = surface.nodes()[face.nodes[edge[c][side][0]]];
          const auto &b         = surface.nodes()[face.nodes[edge[c][side][1]]];
          bool        on_border = false;
          for (unsigned int d = 0; d < 2; ++d)
            for (const double at : {0., 2.})
              on_border = on_border || (std::abs(a.reference[d] - at) < 1e-12 &&
                                        std::abs(b.reference[d] - at) < 1e-12);
          ++n_edges;
          n_border += on_border ? 1 : 0;
          if (face.continues[c][side] == on_border)
            ++n_wrong;
        }
    std::cout << name << ": " << surface.faces().size() << " faces, " << n_edges
              << " edges, " << n_border << " on the outer border, " << n_wrong
              << " with the wrong continuation" << std::endl;
    return n_wrong;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  unsigned int                     n_wrong = 0;

  Triangulation<3> tria;
  GridGenerator::subdivided_hyper_rectangle(tria,
                                            {2, 2, 1},
                                            Point<3>(0, 0, 0),
                                            Point<3>(2, 2, 1),
                                            true);
  tria.begin_active()->set_refine_flag();
  tria.execute_coarsening_and_refinement();
  n_wrong += wrong_edges(tria, "one cell refined");

  // A neighbour of the refined cell refined, then one of its children
  // next to the first refined cell: levels 0, 1 and 2 on the top.
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->level() == 0 && cell->center()[0] > 1 && cell->center()[1] < 1)
      cell->set_refine_flag();
  tria.execute_coarsening_and_refinement();
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->level() == 1 && cell->center()[0] > 1 &&
        cell->center()[0] < 1.5 && cell->center()[1] < 0.5 &&
        cell->center()[2] > 0.5)
      cell->set_refine_flag();
  tria.execute_coarsening_and_refinement();
  n_wrong += wrong_edges(tria, "levels 0, 1 and 2");

  std::cout << (n_wrong == 0 ? "ok" : "FAILED")
            << "  every inner edge continues, no outer one" << std::endl;
  return n_wrong == 0 ? 0 : 1;
}
