/**
 * Scene "gmsh": a mesh file of quadrilaterals or hexahedra, or of
 * triangles or tetrahedra, first- or second-order.
 */

#include <tribos/base/text.h>
#include <tribos/scene/gmsh_second_order.h>
#include <tribos/scene/mesh_tools.h>
#include <tribos/scene/scene.h>

#include <deal.II/grid/grid_in.h>

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

      std::string mesh_file;
    };



    /**
     * What a gmsh element type number is, for the message that refuses it.
     */
    std::string
    gmsh_element_name(const int type)
    {
      switch (type)
      {
        case 2:
          return "3-node triangles";
        case 4:
          return "4-node tetrahedra";
        case 6:
          return "6-node prisms";
        case 7:
          return "5-node pyramids";
        case 8:
          return "3-node (second-order) lines";
        case 9:
          return "6-node (second-order) triangles";
        case 10:
          return "9-node (second-order) quadrilaterals";
        case 11:
          return "10-node (second-order) tetrahedra";
        case 12:
          return "27-node (second-order) hexahedra";
        case 16:
          return "8-node (second-order) quadrilaterals";
        case 17:
          return "20-node (second-order) hexahedra";
        default:
          return "gmsh element type " + std::to_string(type);
      }
    }



    /**
     * The checks deal.II's reader does not make, before it runs: an ASCII
     * gmsh file (the reader takes a binary one for garbage) that is
     * complete (a file cut inside its element list is read as a mesh with
     * fewer cells, without complaint).
     */
    void
    check_gmsh_file(const std::string &file)
    {
      const std::string name = "Parameter <Scene/Mesh file> = <" + file + ">";
      AssertThrow(std::filesystem::is_regular_file(file),
                  ExcMessage(name + ": the file does not exist."));
      std::ifstream input(file, std::ios::binary);
      std::string   line;
      std::getline(input, line);
      AssertThrow(Text::trim(line) == "$MeshFormat",
                  ExcMessage(name +
                             ": not a gmsh mesh file (its first line is not "
                             "$MeshFormat)."));
      double version   = 0;
      int    file_type = -1;
      std::getline(input, line);
      std::istringstream(line) >> version >> file_type;
      AssertThrow(file_type == 0,
                  ExcMessage(name +
                             ": a binary gmsh file; tribos reads ASCII "
                             "files. Save it with 'gmsh -save -format msh2' "
                             "or 'Mesh.Binary = 0;'."));
      // The last section the file opened, for the message of a cut file.
      std::string section;
      bool        complete = false;
      while (std::getline(input, line))
      {
        line = Text::trim(line);
        if (line == "$EndElements")
          complete = true;
        else if (!line.empty() && line[0] == '$' && line.rfind("$End", 0) != 0)
          section = line;
      }
      AssertThrow(complete,
                  ExcMessage(name + ": the file is incomplete: it ends " +
                             (section.empty() ?
                                std::string("after its header") :
                                "inside its " + section + " section") +
                             " (no $EndElements line: cut while it was "
                             "written or copied?). Write the mesh again."));
    }



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



    /** A second-order mesh file's cells and (@p curved, if not null) their
     * curved geometry; false if @p file is first-order. */
    template <int dim>
    bool
    read_second_order(const std::string  &file,
                      const unsigned int  refinement,
                      Triangulation<dim> &tria,
                      CurvedCells<dim>   *curved)
    {
      std::vector<std::vector<Point<dim>>> coarse;
      if (!GmshSecondOrder::read(file, tria, coarse))
        return false;
      check_one_kind(file, tria);
      if (curved != nullptr)
        curved->support_points =
          GmshSecondOrder::refine(tria, refinement, coarse);
      else
        tria.refine_global(refinement);
      return true;
    }



    template <int dim>
    void
    read_gmsh(const GmshScene    &p,
              const unsigned int  refinement,
              Triangulation<dim> &tria,
              CurvedCells<dim>   *curved)
    {
      check_gmsh_file(p.mesh_file);
      if (read_second_order(p.mesh_file, refinement, tria, curved))
        return;
      GridIn<dim> grid_in;
      grid_in.attach_triangulation(tria);
      std::ifstream input(p.mesh_file);
      try
      {
        grid_in.read_msh(input);
      }
      catch (const ExceptionBase &e)
      {
        // deal.II's message lists its own element codes; say in the
        // user's terms what the file holds and what tribos takes.
        std::ostringstream info;
        e.print_info(info);
        const std::string what  = info.str();
        const std::string key   = "Element Identifier <";
        const auto        start = what.find(key);
        if (start != std::string::npos)
        {
          const int type = std::atoi(what.c_str() + start + key.size());
          AssertThrow(false,
                      ExcMessage(
                        "Parameter <Scene/Mesh file> = <" + p.mesh_file +
                        ">: the mesh has " + gmsh_element_name(type) +
                        ", which tribos does not read. It takes "
                        "quadrilaterals or triangles in 2D, hexahedra or "
                        "tetrahedra in 3D, of order 1 or 2: mesh with "
                        "'Mesh.ElementOrder = 1;' or '= 2;'."));
        }
        std::string        first_line;
        std::istringstream lines(what);
        while (first_line.empty() && std::getline(lines, first_line))
          first_line = Text::trim(first_line);
        AssertThrow(false,
                    ExcMessage(
                      "Parameter <Scene/Mesh file> = <" + p.mesh_file +
                      ">: deal.II cannot read the mesh: " + first_line));
      }
      check_one_kind(p.mesh_file, tria);
      tria.refine_global(refinement);
    }
  } // namespace

  const SceneRegistration gmsh_scene = register_scene<GmshScene>("gmsh");
} // namespace tribos
