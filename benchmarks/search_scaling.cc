/**
 * Benchmark: cost of the contact search (CGAL AABB tree build plus the
 * exact projection of every slave node on its closest face and neighbours,
 * ContactHandler::update) for flat 3D interfaces with n slave nodes,
 * non-matching meshes (m x m slave faces over (m+1) x (m+1) master faces).
 * Writes CSV to stdout: n_slave_nodes, n_master_faces, update seconds
 * (median of 5), microseconds per slave node, and the ratio to n log2 n.
 *
 *   ./build/benchmarks/search_scaling [max_m] > search_scaling.csv
 */

#include <tribos/contact/contact_handler.h>
#include <tribos/scene/scene.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int               max_m = argc > 1 ? std::stoi(argv[1]) : 320;

  std::cout << "n_slave_nodes,n_master_faces,update_seconds,"
               "microseconds_per_node,seconds_per_n_log2_n_times_1e9\n";
  for (unsigned int m = 32; m <= max_m;
       m              = static_cast<unsigned int>(m * std::sqrt(10.)))
  {
    Triangulation<3> lower, upper, tria;
    GridGenerator::subdivided_hyper_rectangle(lower,
                                              {m + 1, m + 1, 1},
                                              Point<3>(0, 0, -0.1),
                                              Point<3>(1, 1, 0),
                                              true);
    GridGenerator::subdivided_hyper_rectangle(upper,
                                              {m, m, 1},
                                              Point<3>(0, 0, -1e-4),
                                              Point<3>(1, 1, 0.1),
                                              true);
    for (const auto &cell : upper.active_cell_iterators())
    {
      cell->set_material_id(1);
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          face->set_boundary_id(face->boundary_id() + 10);
    }
    tribos::merge_bodies<3>({&lower, &upper}, tria);

    FESystem<3>   fe(FE_Q<3>(1), 3);
    DoFHandler<3> dof_handler(tria);
    dof_handler.distribute_dofs(fe);

    tribos::Parameters::Contact     parameters;
    tribos::Parameters::ContactPair pair;
    pair.slave_boundary  = {14};
    pair.master_boundary = {5};
    pair.method          = "penalty";
    pair.normal_penalty  = tribos::Parameters::PenaltyValue::parse("1e3", "");
    pair.tangential_penalty    = pair.normal_penalty;
    pair.friction_coefficient  = 0;
    parameters.pairs           = {pair};
    parameters.tangent         = tribos::Parameters::ContactTangent::consistent;
    parameters.two_pass        = false;
    parameters.smoothing       = tribos::Parameters::MasterSmoothing::none;
    parameters.search_distance = std::numeric_limits<double>::infinity();

    const IndexSet            owned = dof_handler.locally_owned_dofs();
    tribos::ContactHandler<3> handler(
      parameters,
      dof_handler,
      [](const types::material_id) { return 1.; },
      owned,
      MPI_COMM_WORLD);
    TrilinosWrappers::MPI::Vector solution(owned, MPI_COMM_WORLD);

    std::vector<double> times;
    for (unsigned int repeat = 0; repeat < 5; ++repeat)
    {
      Timer timer;
      handler.update(solution, 0.);
      times.push_back(timer.wall_time());
    }
    std::sort(times.begin(), times.end());
    const double       median = times[2];
    const unsigned int n      = (m + 1) * (m + 1);
    std::cout << n << ',' << (m + 1) * (m + 1) << ',' << median << ','
              << 1e6 * median / n << ',' << 1e9 * median / (n * std::log2(n))
              << std::endl;
  }
}
