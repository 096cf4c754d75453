#ifndef tribos_contact_vec3_h
#define tribos_contact_vec3_h

#include <array>
#include <cmath>

namespace tribos
{
  /**
   * A 3-vector of any number type (double or a Sacado AD type). Contact
   * kinematics is written once for 2D and 3D by embedding 2D in the plane
   * z = 0, and once for values and derivatives by templating on the number
   * type, so that the consistent tangent is the exact derivative of the
   * residual that is assembled.
   */
  template <typename Number>
  using Vec3 = std::array<Number, 3>;

  template <typename A>
  inline Vec3<A>
  operator+(const Vec3<A> &a, const Vec3<A> &b)
  {
    return Vec3<A>{{A(a[0] + b[0]), A(a[1] + b[1]), A(a[2] + b[2])}};
  }

  template <typename A>
  inline Vec3<A>
  operator-(const Vec3<A> &a, const Vec3<A> &b)
  {
    return Vec3<A>{{A(a[0] - b[0]), A(a[1] - b[1]), A(a[2] - b[2])}};
  }

  /** s * a for a scalar s (a double, an AD number or an AD expression). */
  template <typename S, typename A>
  inline Vec3<A>
  scale(const S &s, const Vec3<A> &a)
  {
    return Vec3<A>{{A(s * a[0]), A(s * a[1]), A(s * a[2])}};
  }

  template <typename A>
  inline A
  dot(const Vec3<A> &a, const Vec3<A> &b)
  {
    return A(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
  }

  template <typename A>
  inline Vec3<A>
  cross(const Vec3<A> &a, const Vec3<A> &b)
  {
    return Vec3<A>{{A(a[1] * b[2] - a[2] * b[1]),
                    A(a[2] * b[0] - a[0] * b[2]),
                    A(a[0] * b[1] - a[1] * b[0])}};
  }

  template <typename A>
  inline A
  norm(const Vec3<A> &a)
  {
    using std::sqrt;
    return A(sqrt(dot(a, a)));
  }

  /** Convert the entries of a double vector to another number type. */
  template <typename Number>
  inline Vec3<Number>
  to(const Vec3<double> &a)
  {
    return Vec3<Number>{{Number(a[0]), Number(a[1]), Number(a[2])}};
  }
} // namespace tribos

#endif
