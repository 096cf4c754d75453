/**
 * Unit test: the tangent A = dP/dF of every material against central finite
 * differences of P, in 2D and 3D, near the identity and at large strain.
 * Asserts a relative error below 1e-6.
 */

#include <tribos/material/material.h>

#include <cmath>
#include <iostream>
#include <random>

using namespace dealii;

template <int dim>
double
tangent_error(const tribos::Material<dim> &material, const Tensor<2, dim> &F)
{
  Tensor<2, dim> P;
  Tensor<4, dim> A;
  material.evaluate(F, nullptr, nullptr, P, &A);

  const double   h = 1e-6;
  Tensor<4, dim> A_fd;
  for (unsigned int k = 0; k < dim; ++k)
    for (unsigned int l = 0; l < dim; ++l)
    {
      Tensor<2, dim> Fp = F, Fm = F, Pp, Pm;
      Fp[k][l] += h;
      Fm[k][l] -= h;
      material.evaluate(Fp, nullptr, nullptr, Pp, nullptr);
      material.evaluate(Fm, nullptr, nullptr, Pm, nullptr);
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          A_fd[i][j][k][l] = (Pp[i][j] - Pm[i][j]) / (2 * h);
    }
  return (A - A_fd).norm() / A.norm();
}



template <int dim>
bool
check(const std::string &model, std::mt19937 &random)
{
  const auto material = tribos::create_material<dim>(model, 210., 0.3);
  std::uniform_real_distribution<double> uniform(-1, 1);
  bool                                   ok    = true;
  double                                 worst = 0;
  for (const double amplitude : {1e-3, 0.1, 0.4})
    for (unsigned int sample = 0; sample < 20; ++sample)
    {
      Tensor<2, dim> F = unit_symmetric_tensor<dim>();
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          F[i][j] += amplitude * uniform(random);
      if (determinant(F) < 0.2)
        continue;
      const double error = tangent_error(*material, F);
      worst              = std::max(worst, error);
      ok                 = ok && error < 1e-6;
    }
  std::cout << dim << "D " << model << ": max relative tangent error " << worst
            << (ok ? "  ok" : "  FAILED") << std::endl;
  return ok;
}



int
main()
{
  std::mt19937 random(42);
  bool         ok = true;
  for (const std::string model : {"linear elastic", "neo-Hookean"})
  {
    ok = check<2>(model, random) && ok;
    ok = check<3>(model, random) && ok;
  }
  return ok ? 0 : 1;
}
