#include <tribos/scene/scene.h>

#include <deal.II/grid/grid_tools.h>


namespace tribos
{
  Registry<SceneGeometry> &
  scene_registry()
  {
    static Registry<SceneGeometry> scenes("scene");
    return scenes;
  }



  std::shared_ptr<const SceneGeometry>
  parse_scene(const std::string &name, ParameterHandler &prm)
  {
    std::shared_ptr<SceneGeometry> geometry = scene_registry().create(name);
    AssertThrow(geometry != nullptr,
                ExcMessage("Parameter <Scene/Name>: unknown scene <" + name +
                           ">."));
    geometry->parse_parameters(prm);
    return geometry;
  }



  void
  SceneGeometry::create(const unsigned int, Triangulation<2> &) const
  {
    AssertThrow(false,
                ExcMessage("Parameter <Scene/Name> = <" + name +
                           "> is a 3D scene: set Dimension = 3."));
  }



  void
  SceneGeometry::create(const unsigned int, Triangulation<3> &) const
  {
    AssertThrow(false,
                ExcMessage("Parameter <Scene/Name> = <" + name +
                           "> is a 2D scene: set Dimension = 2."));
  }



  std::string
  SceneGeometry::mesh_source() const
  {
    return "Parameter <Scene/Name> = <" + name + ">";
  }



  void
  SceneGeometry::create_curved(const unsigned int refinement,
                               Triangulation<2>  &triangulation,
                               CurvedCells<2> &) const
  {
    create(refinement, triangulation);
  }



  void
  SceneGeometry::create_curved(const unsigned int refinement,
                               Triangulation<3>  &triangulation,
                               CurvedCells<3> &) const
  {
    create(refinement, triangulation);
  }



  unsigned int
  SceneGeometry::mesh_order(const unsigned int) const
  {
    return 1;
  }



  std::vector<std::string>
  SceneGeometry::describe() const
  {
    return {};
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



  template void
  merge_bodies(const std::vector<const Triangulation<2> *> &,
               Triangulation<2> &);
  template void
  merge_bodies(const std::vector<const Triangulation<3> *> &,
               Triangulation<3> &);
} // namespace tribos
