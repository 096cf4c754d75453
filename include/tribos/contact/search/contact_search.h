#ifndef tribos_contact_contact_search_h
#define tribos_contact_contact_search_h

#include <tribos/contact/surface/contact_surface.h>

#include <memory>
#include <vector>

namespace tribos
{
  /**
   * Global contact search: the master faces of a ContactSurface in the
   * current configuration, held in a CGAL AABB tree (3D quadrilaterals as
   * two triangles, 2D segments embedded at z = 0). A query returns the face
   * that holds the closest point of the whole master surface; the exact
   * projection on that face and its neighbours is then the job of the
   * kinematics. Independent of how contact is enforced.
   */
  template <int dim>
  class ContactSearch
  {
  public:
    ContactSearch();
    ContactSearch(ContactSearch &&) noexcept;
    ContactSearch &
    operator=(ContactSearch &&) noexcept;
    ~ContactSearch();

    /**
     * (Re)build the tree for the faces @p faces of @p surface (their
     * numbers, ascending) at @p positions (one per surface node; only the
     * nodes of these faces are read). Under MPI a process holds the faces
     * that can reach its own slave nodes (MasterExchange), not the whole
     * surface.
     */
    void
    build(const ContactSurface<dim>       &surface,
          const std::vector<unsigned int> &faces,
          const std::vector<Vec3<double>> &positions);

    /**
     * The face closest to @p point among those of the tree (its number on
     * the surface), the squared distance to it and, if @p closest_point is
     * not null, the closest point. Returns false if the tree has no faces.
     */
    bool
    closest_face(const Vec3<double> &point,
                 unsigned int       &face,
                 double             &squared_distance,
                 Vec3<double>       *closest_point = nullptr) const;

    /**
     * The faces of the tree (their numbers on the surface, each once)
     * that come closer to @p point than @p reach in every coordinate
     * (a box query: a superset of those within the distance @p reach).
     */
    std::vector<unsigned int>
    faces_near(const Vec3<double> &point, const double reach) const;

  private:
    struct Tree;
    std::unique_ptr<Tree> tree;
  };
} // namespace tribos

#endif
