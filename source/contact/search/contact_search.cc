#include <tribos/contact/search/contact_search.h>

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <iterator>

namespace tribos
{
  namespace
  {
    using Kernel   = CGAL::Simple_cartesian<double>;
    using Point3   = Kernel::Point_3;
    using Segment  = Kernel::Segment_3;
    using Triangle = Kernel::Triangle_3;

    template <int dim>
    struct Primitives;

    template <>
    struct Primitives<2>
    {
      using Element   = Segment;
      using Iterator  = std::vector<Segment>::const_iterator;
      using Primitive = CGAL::AABB_segment_primitive<Kernel, Iterator>;
      using Tree      = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
      static constexpr unsigned int per_face = 1;
    };

    template <>
    struct Primitives<3>
    {
      using Element   = Triangle;
      using Iterator  = std::vector<Triangle>::const_iterator;
      using Primitive = CGAL::AABB_triangle_primitive<Kernel, Iterator>;
      using Tree      = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
      static constexpr unsigned int per_face = 2;
    };

    Point3
    point(const Vec3<double> &x)
    {
      return Point3(x[0], x[1], x[2]);
    }
  } // namespace



  template <int dim>
  struct ContactSearch<dim>::Tree
  {
    std::vector<typename Primitives<dim>::Element> elements;
    /** The face of each element (a quadrilateral gives two triangles). */
    std::vector<unsigned int>      face_of_element;
    typename Primitives<dim>::Tree tree;
  };



  template <int dim>
  ContactSearch<dim>::ContactSearch()
    : tree(std::make_unique<Tree>())
  {
  }



  template <int dim>
  ContactSearch<dim>::~ContactSearch() = default;

  template <int dim>
  ContactSearch<dim>::ContactSearch(ContactSearch &&) noexcept = default;

  template <int dim>
  ContactSearch<dim> &
  ContactSearch<dim>::operator=(ContactSearch &&) noexcept = default;



  template <int dim>
  void
  ContactSearch<dim>::build(const ContactSurface<dim>       &surface,
                            const std::vector<unsigned int> &faces,
                            const std::vector<Vec3<double>> &positions)
  {
    auto &elements = tree->elements;
    auto &owner    = tree->face_of_element;
    elements.clear();
    owner.clear();
    elements.reserve(faces.size() * Primitives<dim>::per_face);
    // A face by its vertices: a segment, or its linear face's triangles.
    surface.shape().template visit<dim>(
      [&](auto kind)
      {
        using Linear = typename decltype(kind)::Linear;
        for (const unsigned int f : faces)
        {
          const auto &n = surface.faces()[f].nodes;
          if constexpr (dim == 2)
            elements.emplace_back(point(positions[n[0]]),
                                  point(positions[n[1]]));
          else
            for (const auto &t : Linear::search_triangles)
              elements.emplace_back(point(positions[n[t[0]]]),
                                    point(positions[n[t[1]]]),
                                    point(positions[n[t[2]]]));
          owner.resize(elements.size(), f);
        }
      });
    tree->tree.clear();
    tree->tree.insert(elements.cbegin(), elements.cend());
    tree->tree.build();
    tree->tree.accelerate_distance_queries();
  }



  template <int dim>
  bool
  ContactSearch<dim>::closest_face(const Vec3<double> &x,
                                   unsigned int       &face,
                                   double             &squared_distance,
                                   Vec3<double>       *closest_point) const
  {
    if (tree->elements.empty())
      return false;
    const auto result = tree->tree.closest_point_and_primitive(point(x));
    face = tree->face_of_element[result.second - tree->elements.cbegin()];
    squared_distance = CGAL::squared_distance(result.first, point(x));
    if (closest_point != nullptr)
      *closest_point = {{CGAL::to_double(result.first.x()),
                         CGAL::to_double(result.first.y()),
                         CGAL::to_double(result.first.z())}};
    return true;
  }

  template <int dim>
  std::vector<unsigned int>
  ContactSearch<dim>::faces_near(const Vec3<double> &x,
                                 const double        reach) const
  {
    std::vector<unsigned int> faces;
    if (tree->elements.empty())
      return faces;
    const CGAL::Bbox_3                              box(x[0] - reach,
                           x[1] - reach,
                           x[2] - reach,
                           x[0] + reach,
                           x[1] + reach,
                           x[2] + reach);
    std::vector<typename Primitives<dim>::Iterator> hits;
    tree->tree.all_intersected_primitives(box, std::back_inserter(hits));
    for (const auto &hit : hits)
      faces.push_back(tree->face_of_element[hit - tree->elements.cbegin()]);
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    return faces;
  }



  template class ContactSearch<2>;
  template class ContactSearch<3>;
} // namespace tribos
