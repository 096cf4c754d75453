#ifndef tribos_contact_rigid_surface_h
#define tribos_contact_rigid_surface_h

#include <tribos/contact/surface/vec3.h>
#include <tribos/parameters/contact.h>

#include <deal.II/base/function_parser.h>

#include <memory>
#include <string>

namespace tribos
{
  using namespace dealii;

  /**
   * A rigid analytic master surface (plane, sphere, cylinder; in 2D the
   * cylinder is a circle) that translates as a function of time. It has no
   * mesh and no dofs: only what the scene needs is paid for. The deformable
   * body is on the side the normal points to (outside of sphere and
   * cylinder).
   */
  template <int dim>
  class RigidSurface
  {
  public:
    explicit RigidSurface(const Parameters::RigidSurface &description);

    const std::string &
    name() const
    {
      return description.name;
    }

    /** The translation of the surface at time @p t. */
    Vec3<double>
    translation(const double t) const;

    /**
     * Closest point @p xbar, unit normal @p n and signed gap @p gap of
     * @p x for the surface translated by @p shift. Templated on the number
     * type so that derivatives come out exactly.
     */
    template <typename Number>
    void
    closest_point(const Vec3<Number> &x,
                  const Vec3<double> &shift,
                  Vec3<Number>       &xbar,
                  Vec3<Number>       &n,
                  Number             &gap) const
    {
      const Vec3<Number> r = x - to<Number>(point + shift);
      if (description.type == "plane")
      {
        n    = to<Number>(direction);
        gap  = dot(r, n);
        xbar = x - scale(gap, n);
        return;
      }
      Vec3<Number> radial = r;
      if (description.type == "cylinder" && dim == 3)
        radial =
          r - scale(dot(r, to<Number>(direction)), to<Number>(direction));
      const Number distance = norm(radial);
      n                     = scale(1. / distance, radial);
      gap                   = distance - description.radius;
      xbar                  = x - scale(gap, n);
    }

    /**
     * Whether a point that moved from @p x_old (surface shifted by
     * @p shift_old) to @p x (shifted by @p shift) went through the
     * surface's interior along the straight relative path, deeper than
     * @p tolerance, although it is outside at both ends: a sphere or
     * cylinder moved through a body in one increment, which the gaps at the
     * end of the increment cannot see (tunnelling). A plane cannot be
     * passed that way (its gap is linear along the path).
     */
    bool
    passed_through(const Vec3<double> &x_old,
                   const Vec3<double> &shift_old,
                   const Vec3<double> &x,
                   const Vec3<double> &shift,
                   const double        tolerance) const;

  private:
    const Parameters::RigidSurface     description;
    Vec3<double>                       point;
    Vec3<double>                       direction;
    std::unique_ptr<FunctionParser<1>> motion;
  };
} // namespace tribos

#endif
