#ifndef tribos_parameters_finite_element_h
#define tribos_parameters_finite_element_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace tribos
{
  namespace Parameters
  {
    /** Subsection `Finite element`: the displacement discretization. */
    struct FiniteElement
    {
      /** Lagrange degree of the displacement field (1 or 2; 0 = as meshed
       * until resolve_degree()). */
      unsigned int degree;
      /** Gauss points per direction (0 = degree + 1 until
       * resolve_degree()). */
      unsigned int n_quadrature_points;
      /** Q1 only: the F-bar element against volumetric locking. */
      bool f_bar;
      /** Axisymmetric 2D model (x = r, y = z). */
      bool axisymmetric;
      /** Split every cell of the scene into triangles (8 per
       * quadrilateral) or tetrahedra (24 per hexahedron) before the
       * finite element is chosen (Cells = simplices). */
      bool split_into_simplices;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /** Polynomial degree = as meshed becomes @p mesh_order (the scene's
       * cells' order), and the default number of quadrature points
       * follows the degree; checks what depends on the degree. */
      void
      resolve_degree(const unsigned int mesh_order);
    };
  } // namespace Parameters
} // namespace tribos

#endif
