#include <tribos/material/linear_elastic.h>
#include <tribos/material/material_model.h>

namespace tribos
{
  template <int dim>
  LinearElastic<dim>::LinearElastic(const double E, const double nu)
    : E(E)
    , lambda(E * nu / ((1 + nu) * (1 - 2 * nu)))
    , mu(E / (2 * (1 + nu)))
  {
  }



  template <int dim>
  void
  LinearElastic<dim>::evaluate(const Tensor<2, dim> &F,
                               const double *,
                               double *,
                               Tensor<2, dim> &P,
                               Tensor<4, dim> *tangent) const
  {
    const Tensor<2, dim> H     = F - unit_symmetric_tensor<dim>();
    const Tensor<2, dim> eps   = 0.5 * (H + transpose(H));
    const double         trace = dealii::trace(eps);
    P                          = 2 * mu * eps;
    for (unsigned int i = 0; i < dim; ++i)
      P[i][i] += lambda * trace;

    if (tangent != nullptr)
    {
      Tensor<4, dim> &A = *tangent;
      A                 = 0;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
        {
          A[i][i][j][j] += lambda;
          A[i][j][i][j] += mu;
          A[i][j][j][i] += mu;
        }
    }
  }



  template <int dim>
  SymmetricTensor<2, 3>
  LinearElastic<dim>::cauchy_stress(const Tensor<2, dim> &F,
                                    const double *) const
  {
    Tensor<2, dim> P;
    evaluate(F, nullptr, nullptr, P, nullptr);
    SymmetricTensor<2, 3> sigma;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        sigma[i][j] = P[i][j];
    if (dim == 2)
      sigma[2][2] = lambda * (F[0][0] - 1 + F[dim - 1][dim - 1] - 1);
    return sigma;
  }

  template <int dim>
  double
  LinearElastic<dim>::stored_energy(const Tensor<2, dim> &F,
                                    const double *) const
  {
    // W = lambda/2 tr(eps)^2 + mu eps : eps (plane strain: eps_33 = 0).
    double trace = 0, squared = 0;
    for (unsigned int i = 0; i < dim; ++i)
    {
      trace += F[i][i] - 1;
      for (unsigned int j = 0; j < dim; ++j)
      {
        const double eps = 0.5 * (F[i][j] + F[j][i]) - (i == j ? 1. : 0.);
        squared += eps * eps;
      }
    }
    return 0.5 * lambda * trace * trace + mu * squared;
  }

  template class LinearElastic<2>;
  template class LinearElastic<3>;



  namespace
  {
    /** Materials/Model = linear elastic. */
    class LinearElasticModel
      : public MaterialInBothDimensions<LinearElasticModel>
    {
    public:
      template <int dim>
      std::unique_ptr<Material<dim>>
      make(const unsigned int /*body*/, const double E, const double nu) const
      {
        return std::make_unique<LinearElastic<dim>>(E, nu);
      }
    };

    // Rank 0: the first of Materials/Model's choices.
    const MaterialRegistration linear_elastic_registration =
      register_material<LinearElasticModel>("linear elastic",
                                            "small strain",
                                            0);
  } // namespace
} // namespace tribos
