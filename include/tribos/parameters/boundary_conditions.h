#ifndef tribos_parameters_boundary_conditions_h
#define tribos_parameters_boundary_conditions_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace tribos
{
  namespace Parameters
  {
    /** One Dirichlet condition: boundary id, constrained components, values. */
    struct DirichletCondition
    {
      unsigned int boundary_id;
      /** Constrained components, e.g. {0, 2} for "xz". */
      std::vector<unsigned int> components;
      /** One expression in x, y, z, t per constrained component. */
      std::vector<std::string> expressions;
    };

    /** One Neumann condition: boundary id and nominal traction vector. */
    struct NeumannCondition
    {
      unsigned int             boundary_id;
      std::vector<std::string> expressions;
    };

    /**
     * Subsection `Boundary conditions`. Lists are separated by ';'; each
     * item is `id : components : expressions` (Dirichlet) or
     * `id : expressions` (Neumann). Expressions are deal.II FunctionParser
     * expressions in x, y, z and the time t.
     */
    struct BoundaryConditions
    {
      std::vector<DirichletCondition> dirichlet;
      std::vector<unsigned int>       symmetry;
      std::vector<NeumannCondition>   neumann;
      std::vector<std::string>        body_force;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /** Check counts against the dimension; throws with a clear message. */
      void
      check(const unsigned int dim) const;
    };
  } // namespace Parameters
} // namespace tribos

#endif
