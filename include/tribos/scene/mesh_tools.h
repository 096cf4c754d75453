#ifndef tribos_scene_mesh_tools_h
#define tribos_scene_mesh_tools_h

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <string>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /** Small helpers shared by the scene generators (source/scene/). */
  namespace MeshTools
  {
    /**
     * Refuse a list of @p size @p what ("coordinates", "cell counts") for
     * entry @p entry unless it has dim values, or 3: the entries' defaults
     * serve 2D and 3D, and 2D uses the first two.
     */
    template <int dim>
    inline void
    check_list_size(const std::size_t  size,
                    const std::string &what,
                    const std::string &entry)
    {
      AssertThrow(size == dim || size == 3,
                  ExcMessage("Parameter <" + entry + "> lists " +
                             std::to_string(size) + " " + what + "; it needs " +
                             std::to_string(dim) +
                             (dim == 2 ? " (or 3: the entries serve 2D and "
                                         "3D, and 2D uses the first two)." :
                                         ".")));
    }

    /** Cell counts of @p counts (first dim entries) times 2^refinement. */
    template <int dim>
    inline std::vector<unsigned int>
    scaled_counts(const std::vector<unsigned int> &counts,
                  const unsigned int               refinement,
                  const std::string               &entry)
    {
      check_list_size<dim>(counts.size(), "cell counts", entry);
      std::vector<unsigned int> result(counts.begin(), counts.begin() + dim);
      for (auto &n : result)
        n <<= refinement;
      return result;
    }

    template <int dim>
    inline Point<dim>
    to_point(const std::vector<double> &values, const std::string &entry)
    {
      check_list_size<dim>(values.size(), "coordinates", entry);
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = values[d];
      return p;
    }

    template <int dim>
    inline void
    shift_boundary_ids(Triangulation<dim> &tria, const unsigned int offset)
    {
      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary())
          face->set_boundary_id(face->boundary_id() + offset);
    }

    template <int dim>
    inline void
    set_material_id(Triangulation<dim> &tria, const unsigned int body)
    {
      for (const auto &cell : tria.active_cell_iterators())
        cell->set_material_id(body);
    }

    /** Box body with colorized ids 2d (min) and 2d+1 (max) plus @p offset. */
    template <int dim>
    inline void
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
  } // namespace MeshTools
} // namespace tribos

#endif
