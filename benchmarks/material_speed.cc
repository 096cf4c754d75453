/**
 * Benchmark: the cost of one material evaluation at a quadrature point, the
 * bulk assembly's inner call (the cylinder's J2 at 1.2M dofs evaluates 1.6M
 * points per process per Newton iteration). For each material, 3D, the
 * stress with and without the tangent on 20000 deformation gradients (half
 * with up to 20 % random stretch and shear, plastic for J2 from the history
 * of half that stretch, half with up to 0.1 %, elastic), repeated 7 times;
 * writes the median nanoseconds per call as CSV:
 *
 *   ./build/benchmarks/material_speed > material_speed.csv
 *
 * doc/data/material_speed.csv has two builds side by side (medians of 5
 * alternating runs, the earlier build's library through LD_LIBRARY_PATH).
 *
 * One process, one thread; run it on a quiet machine and compare two
 * builds in one sitting.
 */

#include <tribos/material/material.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <random>
#include <vector>

using namespace dealii;

namespace
{
  /** Median nanoseconds per call of 7 timed passes over @p F. */
  double
  median_ns(const tribos::Material<3>       &material,
            const std::vector<Tensor<2, 3>> &F,
            const std::vector<double>       &history,
            const bool                       with_tangent,
            double                          &checksum)
  {
    const unsigned int  n_history = material.n_history_variables();
    std::vector<double> new_history(n_history);
    std::vector<double> times;
    for (unsigned int pass = 0; pass < 7; ++pass)
    {
      const auto start = std::chrono::steady_clock::now();
      for (unsigned int k = 0; k < F.size(); ++k)
      {
        Tensor<2, 3> P;
        Tensor<4, 3> A;
        material.evaluate(F[k],
                          n_history ? &history[k * n_history] : nullptr,
                          n_history ? new_history.data() : nullptr,
                          P,
                          with_tangent ? &A : nullptr);
        checksum += P[0][0] + (with_tangent ? A[0][0][0][0] : 0.);
      }
      const auto stop = std::chrono::steady_clock::now();
      times.push_back(
        std::chrono::duration<double, std::nano>(stop - start).count() /
        F.size());
    }
    std::nth_element(times.begin(), times.begin() + 3, times.end());
    return times[3];
  }
} // namespace



int
main()
{
  const unsigned int                     n_points = 20000;
  std::mt19937                           random(1);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::vector<Tensor<2, 3>>              F(n_points), F_previous(n_points);
  for (unsigned int k = 0; k < n_points; ++k)
  {
    F[k] = unit_symmetric_tensor<3>();
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        F[k][i][j] += (k % 2 ? 0.2 : 1e-3) * uniform(random);
    // The converged state of an earlier increment, half way there.
    F_previous[k] = 0.5 * (F[k] + Tensor<2, 3>(unit_symmetric_tensor<3>()));
  }

  std::cout << "material,tangent,ns_per_call,plastic_fraction\n";
  double checksum = 0;
  for (const std::string model :
       {"linear elastic", "neo-Hookean", "J2 plasticity"})
  {
    const auto material =
      tribos::create_material<3>(model,
                                 206.9,
                                 0.29,
                                 {{0.45, 0.715, 16.93, 0.12924}});
    const unsigned int  n_history = material->n_history_variables();
    std::vector<double> history(n_points * n_history);
    unsigned int        n_plastic = 0;
    if (n_history > 0)
    {
      std::vector<double> initial(n_history);
      material->initialize_history(initial.data());
      for (unsigned int k = 0; k < n_points; ++k)
      {
        Tensor<2, 3> P;
        material->evaluate(F_previous[k],
                           initial.data(),
                           &history[k * n_history],
                           P,
                           nullptr);
        std::vector<double> next(n_history);
        material->evaluate(F[k],
                           &history[k * n_history],
                           next.data(),
                           P,
                           nullptr);
        // The equivalent plastic strain is the last history variable.
        n_plastic += (next.back() > history[k * n_history + n_history - 1]);
      }
    }
    for (const bool with_tangent : {false, true})
      std::cout << '"' << model << '"' << ',' << with_tangent << ','
                << median_ns(*material, F, history, with_tangent, checksum)
                << ',' << double(n_plastic) / n_points << '\n';
  }
  // Keeps the evaluations from being optimized away.
  std::cerr << "checksum " << checksum << '\n';
  return 0;
}
