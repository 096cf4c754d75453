#include <tribos/scene/scene.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace tribos
{
  namespace
  {
    /** Cell counts of @p counts (first dim entries) times 2^refinement. */
    template <int dim>
    std::vector<unsigned int>
    scaled_counts(const std::vector<unsigned int> &counts,
                  const unsigned int               refinement,
                  const std::string               &entry)
    {
      AssertThrow(counts.size() >= dim,
                  ExcMessage("Parameter <" + entry + "> needs " +
                             std::to_string(dim) + " cell counts."));
      std::vector<unsigned int> result(counts.begin(), counts.begin() + dim);
      for (auto &n : result)
        n <<= refinement;
      return result;
    }

    template <int dim>
    Point<dim>
    to_point(const std::vector<double> &values, const std::string &entry)
    {
      AssertThrow(values.size() >= dim,
                  ExcMessage("Parameter <" + entry + "> needs " +
                             std::to_string(dim) + " coordinates."));
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = values[d];
      return p;
    }

    template <int dim>
    void
    shift_boundary_ids(Triangulation<dim> &tria, const unsigned int offset)
    {
      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary())
          face->set_boundary_id(face->boundary_id() + offset);
    }

    template <int dim>
    void
    set_material_id(Triangulation<dim> &tria, const unsigned int body)
    {
      for (const auto &cell : tria.active_cell_iterators())
        cell->set_material_id(body);
    }

    /** Box body with colorized ids 2d (min) and 2d+1 (max) plus @p offset. */
    template <int dim>
    void
    make_box(Triangulation<dim>              &tria,
             const std::vector<unsigned int> &counts,
             const Point<dim>                &p1,
             const Point<dim>                &p2,
             const unsigned int               body,
             const unsigned int               id_offset)
    {
      GridGenerator::subdivided_hyper_rectangle(tria, counts, p1, p2, true);
      shift_boundary_ids(tria, id_offset);
      set_material_id(tria, body);
    }



    template <int dim>
    void
    create_block(const Parameters::Scene &p, Triangulation<dim> &tria)
    {
      make_box(tria,
               scaled_counts<dim>(p.block.subdivisions,
                                  p.refinement,
                                  "Scene/Block/Subdivisions"),
               to_point<dim>(p.block.lower_corner, "Scene/Block/Lower corner"),
               to_point<dim>(p.block.upper_corner, "Scene/Block/Upper corner"),
               0,
               0);
    }



    template <int dim>
    void
    create_two_blocks(const Parameters::Scene &p, Triangulation<dim> &tria)
    {
      const auto &s = p.two_blocks;
      const auto  lower_size =
        to_point<dim>(s.lower_size, "Scene/Two blocks/Lower block size");
      const auto upper_size =
        to_point<dim>(s.upper_size, "Scene/Two blocks/Upper block size");

      Triangulation<dim> lower, upper;
      make_box(lower,
               scaled_counts<dim>(s.lower_subdivisions,
                                  p.refinement,
                                  "Scene/Two blocks/Lower subdivisions"),
               Point<dim>(),
               lower_size,
               0,
               0);

      Point<dim> origin;
      origin[0]       = s.upper_offset;
      origin[dim - 1] = lower_size[dim - 1] + s.gap;
      make_box(upper,
               scaled_counts<dim>(s.upper_subdivisions,
                                  p.refinement,
                                  "Scene/Two blocks/Upper subdivisions"),
               origin,
               origin + upper_size,
               1,
               10);
      if (s.upper_bottom_radius > 0)
      {
        // Arc bottom: the lowest point stays at the gap, the corners rise
        // by the sagitta, the top stays flat.
        const double R      = s.upper_bottom_radius;
        const double centre = origin[0] + 0.5 * upper_size[0];
        const double height = upper_size[dim - 1];
        GridTools::transform(
          [&](const Point<dim> &x)
          {
            const double dx     = x[0] - centre;
            const double bottom = R - std::sqrt(R * R - dx * dx);
            Point<dim>   y      = x;
            const double eta    = (x[dim - 1] - origin[dim - 1]) / height;
            y[dim - 1] = origin[dim - 1] + bottom + eta * (height - bottom);
            return y;
          },
          upper);
      }
      merge_bodies<dim>({&lower, &upper}, tria);
    }



    /**
     * The Hertz indenter: lower half disc (2D) or the quarter x, y >= 0 of
     * the lower half ball (3D), lowest point at height @p gap above y/z = 0.
     * Ids: 10 curved surface, 11 flat top, 12 plane x = 0, 13 plane y = 0.
     */
    template <int dim>
    void
    make_indenter(Triangulation<dim> &tria,
                  const double        radius,
                  const double        gap,
                  const unsigned int  n_refinements)
    {
      if (dim == 2)
      {
        // Half disc x >= 0, then rotate by -90 degrees: y <= 0.
        GridGenerator::half_hyper_ball(tria, Point<dim>(), radius);
        tria.refine_global(n_refinements);
        GridTools::transform(
          [](const Point<dim> &x)
          {
            Point<dim> y;
            y[0] = x[1];
            y[1] = -x[0];
            return y;
          },
          tria);
      }
      else
      {
        // Octant x, y, z >= 0, then rotate by -90 degrees about x.
        GridGenerator::quarter_hyper_ball(tria, Point<dim>(), radius);
        tria.refine_global(n_refinements);
        GridTools::transform(
          [](const Point<dim> &x)
          {
            Point<dim> y;
            y[0] = x[0];
            y[1] = x[dim - 1];
            y[2] = -x[1];
            return y;
          },
          tria);
      }
      Tensor<1, dim> shift;
      shift[dim - 1] = radius + gap;
      GridTools::shift(shift, tria);

      const double tolerance = 1e-10 * radius;
      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary())
        {
          const Point<dim> c = face->center();
          if (std::abs(c[dim - 1] - (radius + gap)) < tolerance)
            face->set_boundary_id(11);
          else if (dim == 3 && std::abs(c[0]) < tolerance)
            face->set_boundary_id(12);
          else if (dim == 3 && std::abs(c[1]) < tolerance)
            face->set_boundary_id(13);
          else
            face->set_boundary_id(10);
        }
      set_material_id(tria, 1);
    }



    template <int dim>
    void
    create_cylinder_over_block(const Parameters::Scene &p,
                               Triangulation<dim>      &tria)
    {
      const auto        &s = p.cylinder_over_block;
      Triangulation<dim> block, indenter;

      std::vector<unsigned int> counts(dim, s.block_subdivisions[0]);
      counts[dim - 1] = s.block_subdivisions[1];
      for (auto &n : counts)
        n <<= p.refinement;
      Point<dim> p1, p2;
      for (unsigned int d = 0; d < dim - 1; ++d)
      {
        p1[d] = (dim == 2 ? -0.5 * s.block_width : 0.);
        p2[d] = 0.5 * s.block_width;
      }
      p1[dim - 1] = -s.block_height;
      make_box(block, counts, p1, p2, 0, 0);

      make_indenter(indenter,
                    s.radius,
                    s.gap,
                    s.indenter_refinements + p.refinement);
      if (s.with_block)
        merge_bodies<dim>({&block, &indenter}, tria);
      else
        merge_bodies<dim>({&indenter}, tria);

      // Local refinement at the contact point: the curved surface goes
      // back on its exact manifold so that new vertices lie on the sphere.
      Point<dim> centre, contact_point;
      centre[dim - 1]        = s.radius + s.gap;
      contact_point[dim - 1] = 0.5 * s.gap;
      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary() && face->boundary_id() == 10)
          face->set_all_manifold_ids(1);
      tria.set_manifold(1, SphericalManifold<dim>(centre));
      for (unsigned int cycle = 0; cycle < s.contact_refinements; ++cycle)
      {
        for (const auto &cell : tria.active_cell_iterators())
        {
          // Refine every cell that reaches into the refinement disc.
          double distance = cell->center().distance(contact_point);
          for (const unsigned int v : cell->vertex_indices())
            distance =
              std::min(distance, cell->vertex(v).distance(contact_point));
          if (distance < s.refinement_radius * s.radius)
            cell->set_refine_flag();
        }
        tria.execute_coarsening_and_refinement();
      }
    }



    /**
     * Meridian section [r0, R] x [0, z_top] in three blocks, each refined
     * @p n_refinements times: one at the inner bottom corner and two that
     * meet along the line from the section's centre to the rim corner
     * (R, z_top). The rim corner is then a vertex of two cells: when the
     * lateral face folds onto the plate, the corner's 180 degrees are
     * shared by two cells instead of flattening one.
     */
    void
    create_split_corner_section(Triangulation<2>  &section,
                                const double       r0,
                                const double       R,
                                const double       z_top,
                                const unsigned int n_refinements)
    {
      const double                rm = 0.5 * (r0 + R), zm = 0.5 * z_top;
      const std::vector<Point<2>> vertices = {Point<2>(r0, 0),
                                              Point<2>(rm, 0),
                                              Point<2>(R, 0),
                                              Point<2>(r0, zm),
                                              Point<2>(rm, zm),
                                              Point<2>(r0, z_top),
                                              Point<2>(R, z_top)};
      std::vector<CellData<2>>    cells(3);
      cells[0].vertices = {0, 1, 3, 4};
      cells[1].vertices = {1, 2, 4, 6};
      cells[2].vertices = {3, 4, 5, 6};
      section.create_triangulation(vertices, cells, SubCellData());
      section.refine_global(n_refinements);
    }



    /**
     * The section (r, z) swept over the quarter turn x, y >= 0 in
     * @p n_angles equal angles: hexahedra r x z x angle.
     */
    void
    sweep_section(const Triangulation<2> &section,
                  const unsigned int      n_angles,
                  Triangulation<3>       &result)
    {
      const std::vector<Point<2>> &points     = section.get_vertices();
      const unsigned int           n_vertices = points.size();
      std::vector<Point<3>>        vertices;
      for (unsigned int j = 0; j <= n_angles; ++j)
      {
        const double angle = 0.5 * numbers::PI * j / n_angles;
        for (const Point<2> &p : points)
          vertices.emplace_back(p[0] * std::cos(angle),
                                p[0] * std::sin(angle),
                                p[1]);
      }
      std::vector<CellData<3>> cells;
      for (const auto &cell : section.active_cell_iterators())
        for (unsigned int j = 0; j < n_angles; ++j)
        {
          // (r, z, -angle) is right-handed: the later angle comes first.
          CellData<3> hex;
          hex.vertices.resize(8);
          for (unsigned int v = 0; v < 4; ++v)
          {
            hex.vertices[v]     = (j + 1) * n_vertices + cell->vertex_index(v);
            hex.vertices[v + 4] = j * n_vertices + cell->vertex_index(v);
          }
          cells.push_back(hex);
        }
      result.create_triangulation(vertices, cells, SubCellData());
    }



    /**
     * One eighth of the cylinder (3D): quarter disc x, y >= 0 extruded over
     * the upper half height z in [0, h/2]. 2D: the meridian section
     * [0, r] x [0, h/2]. Ids: 0 plane x = 0, 1 plane y = 0, 2 mid plane,
     * 3 top (plate), 4 lateral surface.
     */
    template <int dim>
    void
    create_cylinder_compression(const Parameters::Scene &p,
                                Triangulation<dim>      &tria)
    {
      const auto        &s           = p.cylinder_compression;
      const unsigned int axial_cells = s.axial_cells << p.refinement;
      const double       tolerance   = 1e-10 * s.radius;

      const unsigned int n_refinements = s.radial_refinements + p.refinement;
      if (s.split_corner)
      {
        if constexpr (dim == 2)
          create_split_corner_section(tria,
                                      0.,
                                      s.radius,
                                      0.5 * s.height,
                                      n_refinements);
        else
        {
          // Inner quarter of the radius: a quarter disc extruded in the
          // section's layers at r0; outside: the section swept around in
          // the disc's arc segments. The disc is refined once less than
          // the section: the fold-over is axisymmetric and needs its
          // resolution in the section, while each refinement of the
          // angles doubles the ring's cells (r = 3: 2304 cells).
          const double     r0 = 0.25 * s.radius;
          Triangulation<2> section;
          create_split_corner_section(section,
                                      r0,
                                      s.radius,
                                      0.5 * s.height,
                                      n_refinements);
          std::vector<double> layers;
          for (const Point<2> &v : section.get_vertices())
            if (std::abs(v[0] - r0) < tolerance)
              layers.push_back(v[1]);
          std::sort(layers.begin(), layers.end());
          Triangulation<2> disc, flat;
          GridGenerator::quarter_hyper_ball(disc, Point<2>(), r0);
          disc.refine_global(std::max(n_refinements, 1u) - 1);
          GridGenerator::flatten_triangulation(disc, flat);
          Triangulation<3> core, ring;
          GridGenerator::extrude_triangulation(flat, layers, core);
          sweep_section(section, 1u << std::max(n_refinements, 1u), ring);
          GridGenerator::merge_triangulations(core,
                                              ring,
                                              tria,
                                              1e-8 * s.radius);
        }
      }
      else if constexpr (dim == 2)
      {
        GridGenerator::subdivided_hyper_rectangle(
          tria,
          {(1u << n_refinements), axial_cells},
          Point<2>(),
          Point<2>(s.radius, 0.5 * s.height));
      }
      else
      {
        Triangulation<2> disc;
        GridGenerator::quarter_hyper_ball(disc, Point<2>(), s.radius);
        disc.refine_global(n_refinements);
        Triangulation<2> flat;
        GridGenerator::flatten_triangulation(disc, flat);
        GridGenerator::extrude_triangulation(flat,
                                             axial_cells + 1,
                                             0.5 * s.height,
                                             tria);
      }

      if (s.imperfection > 0)
        GridTools::transform(
          [&s](const Point<dim> &x)
          {
            const double factor =
              1. - s.imperfection * (1. - 2. * x[dim - 1] / s.height);
            Point<dim> y = x;
            for (unsigned int d = 0; d < dim - 1; ++d)
              y[d] *= factor;
            return y;
          },
          tria);

      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary())
        {
          const Point<dim> c = face->center();
          if (std::abs(c[dim - 1] - 0.5 * s.height) < tolerance)
            face->set_boundary_id(3);
          else if (std::abs(c[dim - 1]) < tolerance)
            face->set_boundary_id(2);
          else if (std::abs(c[0]) < tolerance)
            face->set_boundary_id(0);
          else if (dim == 3 && std::abs(c[1]) < tolerance)
            face->set_boundary_id(1);
          else
            face->set_boundary_id(4);
        }
      set_material_id(tria, 0);
    }



    /**
     * Lower half of a two-layer ring (inner layer body 0, outer layer body
     * 1) with its bottom at y = gap, over a foundation (body 2) with its top
     * at y = 0. Ids: 0 inner surface, 1 outer surface, 2 left end, 3 right
     * end; foundation 10 left, 11 right, 12 bottom, 13 top.
     */
    void
    create_ring_on_foundation(const Parameters::Scene &p,
                              Triangulation<2>        &tria)
    {
      const auto        &s        = p.ring_on_foundation;
      const unsigned int n_radial = s.radial_cells_per_layer << p.refinement;
      const unsigned int n_circumferential = s.circumferential_cells
                                             << p.refinement;

      std::vector<std::vector<double>> steps(2);
      for (unsigned int i = 0; i < n_radial; ++i)
        steps[0].push_back((s.interface_radius - s.inner_radius) / n_radial);
      for (unsigned int i = 0; i < n_radial; ++i)
        steps[0].push_back((s.outer_radius - s.interface_radius) / n_radial);
      steps[1].assign(n_circumferential, numbers::PI / n_circumferential);

      // Parameter space (r, theta), theta in [pi, 2 pi]: the lower half.
      Triangulation<2> ring;
      GridGenerator::subdivided_hyper_rectangle(
        ring,
        steps,
        Point<2>(s.inner_radius, numbers::PI),
        Point<2>(s.outer_radius, 2 * numbers::PI),
        true);
      for (const auto &cell : ring.active_cell_iterators())
        cell->set_material_id(cell->center()[0] < s.interface_radius ? 0 : 1);

      const double centre_height = s.outer_radius + s.gap;
      GridTools::transform(
        [centre_height](const Point<2> &q)
        {
          return Point<2>(q[0] * std::cos(q[1]),
                          centre_height + q[0] * std::sin(q[1]));
        },
        ring);

      Triangulation<2> foundation;
      make_box(foundation,
               {s.foundation_cells[0] << p.refinement,
                s.foundation_cells[1] << p.refinement},
               Point<2>(-0.5 * s.foundation_width, -s.foundation_height),
               Point<2>(0.5 * s.foundation_width, 0),
               2,
               10);
      merge_bodies<2>({&ring, &foundation}, tria);
    }



    template <int dim>
    void
    read_gmsh(const Parameters::Scene &p, Triangulation<dim> &tria)
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
      tria.refine_global(p.refinement);
    }
  } // namespace



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
    const std::string &name = parameters.name;
    if (name == "block")
      create_block(parameters, triangulation);
    else if (name == "two blocks")
      create_two_blocks(parameters, triangulation);
    else if (name == "cylinder over block")
      create_cylinder_over_block(parameters, triangulation);
    else if (name == "cylinder compression")
      create_cylinder_compression(parameters, triangulation);
    else if (name == "ring on foundation")
    {
      if constexpr (dim == 2)
        create_ring_on_foundation(parameters, triangulation);
      else
        AssertThrow(false,
                    ExcMessage("Parameter <Scene/Name> = <ring on "
                               "foundation> is a 2D scene: set "
                               "Dimension = 2."));
    }
    else if (name == "gmsh")
      read_gmsh(parameters, triangulation);
    else
      AssertThrow(false,
                  ExcMessage("Parameter <Scene/Name>: unknown scene <" + name +
                             ">."));
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
