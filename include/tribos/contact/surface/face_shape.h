#ifndef tribos_contact_surface_face_shape_h
#define tribos_contact_surface_face_shape_h

#include <tribos/contact/surface/face_kinds.h>

#include <deal.II/base/exceptions.h>

#include <functional>
#include <string>
#include <type_traits>
#include <variant>

namespace tribos
{
  /**
   * The kind of a contact surface's faces (face_kinds.h), chosen once when
   * the surface is built (for_cells()) and asked wherever a face's nodes,
   * shape functions or tables differ by kind. Code that is written per kind
   * visits the shape with a generic lambda, which receives the kind (an
   * empty struct) and reads its static members; the lambda is compiled for
   * every kind of the dimension, so a kind that lacks what the code needs
   * does not compile, where a test of a node count would fall silently into
   * its last branch.
   *
   * Two bytes, trivially copyable.
   */
  class FaceShape
  {
  public:
    using Kind = std::variant<Segment2,
                              Segment3,
                              Quadrilateral4,
                              Triangle3,
                              Triangle6,
                              Quadrilateral9>;

    /** The most nodes a face has (the nine-node quadrilateral). */
    static constexpr unsigned int max_nodes = 9;

    /** The shape of kind @p K. */
    template <class K>
    static constexpr FaceShape
    of()
    {
      return FaceShape(Kind(K{}));
    }

    /**
     * The faces of a mesh of dimension @p dim whose cells are all
     * hypercubes (@p hyper_cubes) or all simplices, with finite elements of
     * polynomial degree @p degree (1 or 2; others are refused with a
     * message).
     */
    static FaceShape
    for_cells(const int dim, const bool hyper_cubes, const unsigned int degree);

    /** The dimension of the mesh whose faces these are. */
    int
    dim() const
    {
      return std::visit([](auto k) { return decltype(k)::dim; }, kind);
    }

    unsigned int
    n_vertices() const
    {
      return std::visit([](auto k) { return decltype(k)::n_vertices; }, kind);
    }

    /** The nodes after the vertices: the middles of edges, a centre. */
    unsigned int
    n_middles() const
    {
      return std::visit([](auto k) { return decltype(k)::n_middles; }, kind);
    }

    unsigned int
    n_nodes() const
    {
      return std::visit([](auto k) { return decltype(k)::n_nodes; }, kind);
    }

    /** The polynomial degree of the face's functions. */
    unsigned int
    degree() const
    {
      return std::visit([](auto k) { return decltype(k)::degree; }, kind);
    }

    /** The linear face on the same vertices. */
    FaceShape
    linear() const
    {
      return std::visit([](auto k)
                        { return of<typename decltype(k)::Linear>(); },
                        kind);
    }

    /** Whether the faces are triangles (linear or six-node). */
    bool
    triangle() const
    {
      return linear() == of<Triangle3>();
    }

    /** A name for messages, e.g. "six-node triangle". */
    std::string
    name() const;

    /**
     * The integrals over a face with nodes at @p x (all its nodes) of its
     * nodes' functions (the six-node triangle's modified basis), times
     * 2 pi r with @p axisymmetric (2D, r = x), given node by node to
     * @p add(node, integral, measure) with the face's measure at the same
     * points (without 2 pi r). Linear faces and straight quadratic ones
     * (@p curved false) on their chords, curved ones on their quadratic
     * geometry; nine-node quadrilaterals always on theirs.
     */
    void
    integrate(
      const Vec3<double>                                      *x,
      const bool                                               axisymmetric,
      const bool                                               curved,
      const std::function<void(unsigned int, double, double)> &add) const;

    /**
     * @p f called with the kind, which must be one of dimension @p dim
     * (else an internal error): @p f is compiled for those kinds only.
     */
    template <int dim, class F>
    decltype(auto)
    visit(F &&f) const
    {
      using First  = LinearFace<dim>;
      using Result = decltype(f(First{}));
      return std::visit(
        [&](auto k) -> Result
        {
          if constexpr (decltype(k)::dim == dim)
            return f(k);
          else
          {
            AssertThrow(false, dealii::ExcInternalError());
            return f(First{});
          }
        },
        kind);
    }

    /**
     * visit() for the linear kinds, those the node-to-segment elements and
     * the smoothed masters take (a quadratic kind is an internal error).
     */
    template <int dim, class F>
    decltype(auto)
    visit_linear(F &&f) const
    {
      using Result = decltype(f(LinearFace<dim>{}));
      return visit<dim>(
        [&](auto k) -> Result
        {
          if constexpr (decltype(k)::degree == 1)
            return f(k);
          else
          {
            AssertThrow(false, dealii::ExcInternalError());
            return f(LinearFace<dim>{});
          }
        });
    }

    bool
    operator==(const FaceShape &other) const
    {
      return kind.index() == other.kind.index();
    }

    bool
    operator!=(const FaceShape &other) const
    {
      return !(*this == other);
    }

  private:
    constexpr explicit FaceShape(const Kind &kind)
      : kind(kind)
    {
    }

    Kind kind;
  };
} // namespace tribos

#endif
