#include <tribos/contact/surface/rigid_surface.h>

#include <deal.II/lac/vector.h>

#include <algorithm>

namespace tribos
{
  template <int dim>
  RigidSurface<dim>::RigidSurface(const Parameters::RigidSurface &description)
    : description(description)
  {
    for (unsigned int d = 0; d < 3; ++d)
      point[d] = description.point[d];
    direction                 = {{0, 0, 0}};
    const bool uses_direction = description.type == "plane" ||
                                (description.type == "cylinder" && dim == 3);
    if (uses_direction)
    {
      for (unsigned int d = 0; d < 3; ++d)
        direction[d] = description.direction[d];
      const double length = norm(direction);
      AssertThrow(length > 0,
                  ExcMessage("Parameter <Contact/Rigid surfaces>: surface <" +
                             description.name +
                             "> has a zero normal or axis."));
      direction = scale(1. / length, direction);
      AssertThrow(dim == 3 || std::abs(direction[2]) == 0,
                  ExcMessage("Parameter <Contact/Rigid surfaces>: surface <" +
                             description.name +
                             "> must have a zero z-component in 2D."));
    }

    std::string expressions;
    for (unsigned int d = 0; d < dim; ++d)
      expressions += (d ? ";" : "") + description.motion[d];
    motion = std::make_unique<FunctionParser<1>>(dim);
    try
    {
      // The motion depends on time only; x is a dummy variable.
      motion->initialize("x_dummy,t", expressions, {{"pi", numbers::PI}}, true);
      dealii::Vector<double> value(dim);
      motion->vector_value(Point<1>(), value);
    }
    catch (...)
    {
      AssertThrow(false,
                  ExcMessage("Parameter <Contact/Rigid surfaces>: cannot "
                             "parse the motion <" +
                             expressions + "> of surface <" + description.name +
                             ">. Use expressions in t."));
    }
  }



  template <int dim>
  Vec3<double>
  RigidSurface<dim>::translation(const double t) const
  {
    motion->set_time(t);
    dealii::Vector<double> value(dim);
    motion->vector_value(Point<1>(), value);
    Vec3<double> shift{{0, 0, 0}};
    for (unsigned int d = 0; d < dim; ++d)
      shift[d] = value[d];
    return shift;
  }



  template <int dim>
  bool
  RigidSurface<dim>::passed_through(const Vec3<double> &x_old,
                                    const Vec3<double> &shift_old,
                                    const Vec3<double> &x,
                                    const Vec3<double> &shift,
                                    const double        tolerance) const
  {
    if (description.type == "plane")
      return false;
    // The path relative to the centre (sphere, circle) or the axis
    // (cylinder), from a to b.
    const auto radial = [&](const Vec3<double> &r)
    {
      return description.type == "cylinder" && dim == 3 ?
               r - scale(dot(r, direction), direction) :
               r;
    };
    const Vec3<double> a = radial(x_old - (point + shift_old));
    const Vec3<double> b = radial(x - (point + shift));
    const double       R = description.radius;
    if (norm(a) <= R || norm(b) <= R)
      return false;
    const Vec3<double> d  = b - a;
    const double       dd = dot(d, d);
    if (dd == 0)
      return false;
    const double t = std::clamp(-dot(a, d) / dd, 0., 1.);
    return norm(a + scale(t, d)) < R - tolerance;
  }



  template class RigidSurface<2>;
  template class RigidSurface<3>;
} // namespace tribos
