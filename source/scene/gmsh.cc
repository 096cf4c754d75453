/**
 * Scene "gmsh": a mesh file of quadrilaterals or hexahedra.
 */

#include <tribos/scene/mesh_tools.h>
#include <tribos/scene/scene.h>

#include <deal.II/grid/grid_in.h>

#include <filesystem>
#include <fstream>
#include <memory>

namespace tribos
{
  using namespace MeshTools;

  namespace
  {
    class GmshScene;

    template <int dim>
    void
    read_gmsh(const GmshScene    &p,
              const unsigned int  refinement,
              Triangulation<dim> &tria);



    /** Scene "gmsh": a mesh file (entry Scene/Mesh file). */
    class GmshScene : public SceneInBothDimensions<GmshScene>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Mesh file",
                          "",
                          Patterns::Anything(),
                          "Gmsh .msh file for Name = gmsh: physical tags of "
                          "cells become body ids, of faces boundary ids.");
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        mesh_file = prm.get("Mesh file");
      }

      /** The scene in dim dimensions. */
      template <int dim>
      void
      build(const unsigned int refinement, Triangulation<dim> &tria) const
      {
        read_gmsh(*this, refinement, tria);
      }

      std::string mesh_file;
    };



    template <int dim>
    void
    read_gmsh(const GmshScene    &p,
              const unsigned int  refinement,
              Triangulation<dim> &tria)
    {
      AssertThrow(std::filesystem::is_regular_file(p.mesh_file),
                  ExcMessage("Parameter <Scene/Mesh file> = <" + p.mesh_file +
                             ">: the file does not exist."));
      GridIn<dim> grid_in;
      grid_in.attach_triangulation(tria);
      std::ifstream input(p.mesh_file);
      grid_in.read_msh(input);
      // Simplices would crash deal.II's FE_Q (segmentation fault in
      // DoFHandler::distribute_dofs): refuse them here with the remedy.
      AssertThrow(tria.all_reference_cells_are_hyper_cube(),
                  ExcMessage(
                    "Parameter <Scene/Mesh file> = <" + p.mesh_file +
                    ">: the mesh has triangles or tetrahedra (alone or "
                    "mixed with quadrilaterals). tribos supports "
                    "quadrilaterals (2D) and hexahedra (3D) only. In gmsh, "
                    "recombine the mesh: 'Mesh.RecombineAll = 1;' (2D "
                    "quadrilaterals; with 'Mesh.SubdivisionAlgorithm = 1;' "
                    "no triangle is left) or, in 3D, a structured "
                    "(transfinite, recombined, extruded) hexahedral mesh, "
                    "or 'Mesh.SubdivisionAlgorithm = 2;' (tetrahedra split "
                    "into hexahedra)."));
      tria.refine_global(refinement);
    }
  } // namespace

  const SceneRegistration gmsh_scene = register_scene<GmshScene>("gmsh");
} // namespace tribos
