#include <tribos/scene/scene.h>

#include <deal.II/grid/grid_tools.h>

#include <map>

namespace tribos
{
  namespace
  {
    struct Generators
    {
      SceneGenerator<2> two   = nullptr;
      SceneGenerator<3> three = nullptr;
    };

    /** The registered scenes, by name (built during static
     * initialization, hence a function-local static). */
    std::map<std::string, Generators> &
    registry()
    {
      static std::map<std::string, Generators> scenes;
      return scenes;
    }
  } // namespace



  SceneRegistration::SceneRegistration(const std::string &name,
                                       const SceneGenerator<2> two,
                                       const SceneGenerator<3> three)
  {
    registry()[name] = {two, three};
  }



  std::vector<std::string>
  scene_names()
  {
    std::vector<std::string> names;
    for (const auto &[name, generators] : registry())
      names.push_back(name);
    return names;
  }



  template <int dim>
  void
  merge_bodies(const std::vector<const Triangulation<dim> *> &bodies,
               Triangulation<dim>                            &result)
  {
    std::vector<Point<dim>>    vertices;
    std::vector<CellData<dim>> cells;
    SubCellData                boundary;

    for (const auto *body : bodies)
    {
      const unsigned int offset = vertices.size();
      vertices.insert(vertices.end(),
                      body->get_vertices().begin(),
                      body->get_vertices().end());
      for (const auto &cell : body->active_cell_iterators())
      {
        CellData<dim> data(cell->n_vertices());
        for (const unsigned int v : cell->vertex_indices())
          data.vertices[v] = offset + cell->vertex_index(v);
        data.material_id = cell->material_id();
        cells.push_back(data);

        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() != 0)
          {
            CellData<dim - 1> face_data(face->n_vertices());
            for (const unsigned int v : face->vertex_indices())
              face_data.vertices[v] = offset + face->vertex_index(v);
            face_data.boundary_id = face->boundary_id();
            if constexpr (dim == 2)
              boundary.boundary_lines.push_back(face_data);
            else
              boundary.boundary_quads.push_back(face_data);
          }
      }
    }
    GridTools::delete_unused_vertices(vertices, cells, boundary);
    result.create_triangulation(vertices, cells, boundary);
  }



  template <int dim>
  void
  create_scene(const Parameters::Scene &parameters,
               Triangulation<dim>      &triangulation)
  {
    const auto scene = registry().find(parameters.name);
    AssertThrow(scene != registry().end(),
                ExcMessage("Parameter <Scene/Name>: unknown scene <" +
                           parameters.name + ">."));
    if constexpr (dim == 2)
    {
      AssertThrow(scene->second.two != nullptr,
                  ExcMessage("Parameter <Scene/Name> = <" + parameters.name +
                             "> is a 3D scene: set Dimension = 3."));
      scene->second.two(parameters, triangulation);
    }
    else
    {
      AssertThrow(scene->second.three != nullptr,
                  ExcMessage("Parameter <Scene/Name> = <" + parameters.name +
                             "> is a 2D scene: set Dimension = 2."));
      scene->second.three(parameters, triangulation);
    }
  }

  template void
  create_scene(const Parameters::Scene &, Triangulation<2> &);
  template void
  create_scene(const Parameters::Scene &, Triangulation<3> &);
  template void
  merge_bodies(const std::vector<const Triangulation<2> *> &,
               Triangulation<2> &);
  template void
  merge_bodies(const std::vector<const Triangulation<3> *> &,
               Triangulation<3> &);
} // namespace tribos
