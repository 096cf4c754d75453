/**
 * Scene "gmsh": a mesh file of quadrilaterals or hexahedra, or of
 * triangles or tetrahedra, first- or second-order.
 */

#include <tribos/base/text.h>
#include <tribos/scene/gmsh_second_order.h>
#include <tribos/scene/mesh_tools.h>
#include <tribos/scene/scene.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

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
              Triangulation<dim> &tria,
              CurvedCells<dim>   *curved);



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

      /** The scene in dim dimensions (a second-order mesh's cells
       * straight). */
      template <int dim>
      void
      build(const unsigned int refinement, Triangulation<dim> &tria) const
      {
        read_gmsh<dim>(*this, refinement, tria, nullptr);
      }

      void
      create_curved(const unsigned int refinement,
                    Triangulation<2>  &tria,
                    CurvedCells<2>    &curved) const override
      {
        read_gmsh(*this, refinement, tria, &curved);
      }

      void
      create_curved(const unsigned int refinement,
                    Triangulation<3>  &tria,
                    CurvedCells<3>    &curved) const override
      {
        read_gmsh(*this, refinement, tria, &curved);
      }

      unsigned int
      mesh_order(const unsigned int dim) const override
      {
        return dim == 2 ? GmshSecondOrder::order<2>(mesh_file) :
                          GmshSecondOrder::order<3>(mesh_file);
      }

      std::string
      mesh_source() const override
      {
        return "Parameter <Scene/Mesh file> = <" + mesh_file + ">";
      }

      std::string mesh_file;
    };



    /** Refuse a mesh of more than one kind of cell: the finite element
     * follows the kind (FE_Q or FE_SimplexP). */
    template <int dim>
    void
    check_one_kind(const std::string &file, const Triangulation<dim> &tria)
    {
      AssertThrow(tria.all_reference_cells_are_hyper_cube() ||
                    tria.all_reference_cells_are_simplex(),
                  ExcMessage(
                    "Parameter <Scene/Mesh file> = <" + file +
                    ">: the mesh mixes triangles or tetrahedra with "
                    "quadrilaterals or hexahedra (or has prisms or "
                    "pyramids). tribos takes one kind of cell per mesh: in "
                    "gmsh, 'Mesh.RecombineAll = 1;' with "
                    "'Mesh.SubdivisionAlgorithm = 1;' (2D) or '= 2;' (3D) "
                    "leaves quadrilaterals or hexahedra only; without "
                    "recombination the mesh is all triangles or "
                    "tetrahedra."));
    }



    template <int dim>
    void
    read_gmsh(const GmshScene    &p,
              const unsigned int  refinement,
              Triangulation<dim> &tria,
              CurvedCells<dim>   *curved)
    {
      AssertThrow(!p.mesh_file.empty(),
                  ExcMessage("Parameter <Scene/Mesh file> is empty: Scene/"
                             "Name = gmsh needs a gmsh .msh file."));
      std::vector<std::vector<Point<dim>>> coarse;
      const bool                           second_order =
        GmshSecondOrder::read(p.mesh_file, tria, coarse);
      check_one_kind(p.mesh_file, tria);
      if (second_order && curved != nullptr)
        curved->support_points =
          GmshSecondOrder::refine(tria, refinement, coarse);
      else
        tria.refine_global(refinement);
    }
  } // namespace

  const SceneRegistration gmsh_scene = register_scene<GmshScene>("gmsh");
} // namespace tribos
