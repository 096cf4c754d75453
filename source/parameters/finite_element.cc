#include <tribos/parameters/finite_element.h>

#include <string>

namespace tribos
{
  namespace Parameters
  {
    void
    FiniteElement::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Finite element");
      prm.declare_entry("Polynomial degree",
                        "as meshed",
                        dealii::Patterns::Selection("as meshed|1|2"),
                        "Degree of the Lagrange displacement element: 1 (Q1, "
                        "P1 on triangles and tetrahedra) or 2 (Q2, P2); as "
                        "meshed: 2 for a second-order gmsh mesh (tri6, quad8, "
                        "quad9, tet10, hex20, hex27: its curved geometry "
                        "kept), else 1.");
      prm.declare_entry("Quadrature points",
                        "0",
                        dealii::Patterns::Integer(0, 6),
                        "Gauss points per direction; 0 chooses degree + 1.");
      prm.declare_entry("F-bar",
                        "false",
                        dealii::Patterns::Bool(),
                        "Q1 only: the F-bar element (the volume change of "
                        "each quadrature point replaced by that of the cell "
                        "centre) against locking in isochoric plastic "
                        "flow (axisymmetric: the 3D volume change, hoop "
                        "stretch included).");
      prm.declare_entry("Axisymmetric",
                        "false",
                        dealii::Patterns::Bool(),
                        "Dimension = 2 only: an axisymmetric model, x = "
                        "radius r >= 0, y = axial coordinate z, about the y "
                        "axis; the hoop stretch 1 + u_r / r enters a 3D "
                        "material, every integral carries 2 pi r (forces "
                        "and reactions are those of the full 360 degrees), "
                        "and stress_zz is the hoop stress. The axis needs "
                        "u_r = 0 (Symmetry or Dirichlet).");
      prm.declare_entry(
        "Cells",
        "as meshed",
        dealii::Patterns::Selection("as meshed|simplices"),
        "as meshed: the scene's cells (quadrilaterals and hexahedra, or the "
        "triangles and tetrahedra of a gmsh mesh); simplices: every cell of "
        "the scene split into triangles (8 per quadrilateral) or tetrahedra "
        "(24 per hexahedron), with the same boundary and body ids.");
      prm.leave_subsection();
    }



    void
    FiniteElement::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Finite element");
      const std::string degree_text = prm.get("Polynomial degree");
      degree = degree_text == "as meshed" ? 0 : std::stoi(degree_text);
      n_quadrature_points  = prm.get_integer("Quadrature points");
      f_bar                = prm.get_bool("F-bar");
      axisymmetric         = prm.get_bool("Axisymmetric");
      split_into_simplices = prm.get("Cells") == "simplices";
      prm.leave_subsection();
    }



    void
    FiniteElement::resolve_degree(const unsigned int mesh_order)
    {
      if (degree == 0)
        degree = mesh_order;
      if (n_quadrature_points == 0)
        n_quadrature_points = degree + 1;
      AssertThrow(!f_bar || degree == 1,
                  dealii::ExcMessage(
                    "Parameter <Finite element/F-bar> = true needs Polynomial "
                    "degree = 1" +
                    std::string(mesh_order == 2 ?
                                  " (as meshed, the second-order mesh gives "
                                  "2: set Polynomial degree = 1)" :
                                  "") +
                    "."));
    }
  } // namespace Parameters
} // namespace tribos
