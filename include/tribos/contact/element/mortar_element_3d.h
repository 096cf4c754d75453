#ifndef tribos_contact_mortar_element_3d_h
#define tribos_contact_mortar_element_3d_h

#include <tribos/contact/element/contact_element.h>

#include <deal.II/base/types.h>

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace tribos
{
  /**
   * The overlaps of (slave face, master face) pairs integrated so far in
   * one assembly: each overlap is needed by the elements of the 4 nodes of
   * its slave face and is integrated once. Clear it whenever the
   * positions change.
   */
  struct MortarOverlapCache
  {
    /** The AD number of one overlap: the coordinates of its slave and
     * master pieces' nodes (a face, or a flat piece of a quadratic one: a
     * triangle of a six-node triangle, a bilinear quarter of a nine-node
     * quadrilateral), 4 + 4 at most, the master's from 12 on. */
    using FaceAD = Sacado::Fad::SLFad<double, 24>;

    /** Whether the pieces overlap and, if so, the overlap's area and the
     * integrals int N_i N_k (slave face's functions, n_s x n_s, row-major)
     * and int N_i N_l (slave x master face's, n_s x n_m) over it. */
    struct Entry
    {
      bool                overlaps = false;
      FaceAD              area;
      std::vector<FaceAD> slave, master;
    };

    /** By slave piece (high 32 bits: 4 times the face's number plus the
     * piece's) and master piece (low 32 bits, the same). */
    std::unordered_map<std::uint64_t, Entry> entries;
  };



  /**
   * A face of the mortar element: its nodes' local numbers, 4 of a
   * bilinear quadrilateral (lexicographic), 3 of a triangle
   * (TriangleFace), 6 of a quadratic triangle (vertices, then the
   * middles of the edges 0-1, 1-2, 2-0) or 9 of a biquadratic
   * quadrilateral (the lexicographic vertices, the middles of the edges
   * 0-1, 2-3, 0-2, 1-3, the centre: ContactSurface::Face's order).
   */
  struct MortarFace3D
  {
    /** The most nodes of a face: the nine-node quadrilateral's. */
    static constexpr unsigned int       max_nodes = 9;
    std::array<unsigned int, max_nodes> nodes{};
    unsigned int                        n = 4;
    unsigned int
    operator[](const unsigned int i) const
    {
      return nodes[i];
    }
  };



  /**
   * What the 3D mortar element of one slave node j needs: the slave nodes
   * of its faces (j first, then its neighbours), now and at the last
   * converged step, the faces (bilinear quadrilaterals in deal.II's
   * lexicographic vertex order, or triangles, ordered so that the
   * MasterFace or TriangleFace normal points out of the slave body) in
   * those local numbers,
   * and the master nodes and faces that the search found facing them.
   */
  struct MortarInput3D
  {
    /** Faces around a node: 4 on a structured surface, 3 to 6 where the
     * mesh is irregular (a sphere's), and one more per hanging node the
     * node carries (ContactPair::carried, at most 4); triangles: 4 to 8
     * on split cubes, up to 12 on a gmsh surface. */
    static constexpr unsigned int max_slave_faces = 16;
    /** Two more nodes per face around a linear node, up to three around a
     * vertex of quadratic triangles. */
    static constexpr unsigned int max_slave_nodes = 1 + 3 * max_slave_faces;
    unsigned int                  n_slave_nodes   = 0;
    Vec3<double>                  xs[max_slave_nodes], xs_old[max_slave_nodes];
    unsigned int                  n_slave_faces = 0;
    MortarFace3D                  slave_face[max_slave_faces];
    /**
     * Per slave face, the nodes whose multiplier functions the element
     * integrates on it (their positions 0-3 in the face) with their
     * weights: node j (local number 0) with 1, and the hanging nodes it
     * carries with its weight in their constraints. The element's function
     * is Phi_j + sum_h c_h Phi_h.
     */
    unsigned int                                   n_carriers[max_slave_faces];
    std::array<std::pair<unsigned int, double>, 4> carriers[max_slave_faces];

    unsigned int n_master_nodes = 0;
    Vec3<double> xm[max_mortar_master_nodes_3d],
      xm_old[max_mortar_master_nodes_3d];
    unsigned int n_master_faces = 0;
    MortarFace3D master_face[max_mortar_master_nodes_3d];

    /** Mortar basis = dual (else standard). */
    bool dual = true;
    /** A node whose weight w_j is below this has no master. */
    double min_weight = 0;
    /** The share of the contact this element carries (ContactPair::
     * area_factor: one half for each side of a self-contact pair with
     * penalty): its forces and the area it reports are scaled by it. */
    double area_factor = 1;

    /** The surfaces' numbers of the slave and master faces (the keys of
     * the cache) and the assembly's cache of overlaps (none: each element
     * integrates its overlaps itself). */
    unsigned int        slave_face_id[max_slave_faces];
    unsigned int        master_face_id[max_mortar_master_nodes_3d];
    MortarOverlapCache *cache = nullptr;
  };



  /**
   * The mortar (segment-to-segment) element of slave node j in 3D, after
   * Puso and Laursen (2004) and Popp, Gee and Wall (2010): the 2D element
   * (Mortar2D) with faces for segments. Each slave face and each master
   * face facing it are projected along the slave face's normal n_0 at its
   * centre onto the auxiliary plane through that centre; the two
   * quadrilaterals are clipped there (Sutherland-Hodgman, the slave's
   * projection is convex), the clip polygon (convex) is split into a fan
   * of triangles from its first vertex, and each triangle is integrated by the
   * 7-point rule of degree 5. At each point the slave and master coordinates xi
   * are the inverse of their projected bilinear maps (Newton). With them
   *
   *   D_jk = int Phi_j N_k,   M_jl = int Phi_j N_l,   w_j = sum_k D_jk,
   *
   * integrated in the plane's measure, and the same weighted gap, slip,
   * nodal normal (the faces' n_0 weighted by their share of w_j) and force
   * as in 2D. For a flat interface and parallelogram faces every integrand
   * is a polynomial of degree 4 in the plane, so the rule is exact and the
   * contact patch test holds to round-off with either side as slave.
   *
   * Dual basis: Phi = A N on each slave face with A = D_e M_e^-1 (M_e the
   * face's mass matrix in the plane's measure, 2 x 2 Gauss, exact), blended
   * towards the standard functions on faces the master covers only in part
   * (theta = 2 c - 1 for a covered fraction c in [1/2, 1]), as in 2D.
   *
   * Quadratic faces (six-node triangles, nine-node quadrilaterals) are
   * clipped and integrated on their four flat pieces, the quadratic
   * functions evaluated at each point's coordinates in the face, and
   * their dual functions are biorthogonal to a modified basis
   * (modified_basis() in the source; doc/simplex.md).
   *
   * Everything, the projections, the clipping and the inverse maps
   * included, is Sacado AD of the positions: the tangent is exact. Each
   * overlap is integrated in an AD number of its own 24 coordinates (the
   * slave and master faces' nodes) and its integrals are carried over to
   * the node's: the quadrature, most of the work, then runs on 24
   * derivatives instead of the node's 80-150 (2.8 times faster).
   */
  struct Mortar3D
  {
    /**
     * Evaluate the element of slave node j (@p input) with the law of
     * @p enforcement. Dofs: the slave nodes of input (3 each), the master
     * nodes (3 each), then the enforcement's unknowns; otherwise as
     * Mortar2D::evaluate().
     */
    static ContactPointResult
    evaluate(const SlaveInput     &slave,
             const MortarInput3D  &input,
             const Enforcement<3> &enforcement,
             double               *R,
             double               *K,
             bool                 &paired,
             Vec3<double>         &weighted_point);
  };

  namespace internal
  {
    /**
     * The intersection of the convex polygon @p clip (counter-clockwise,
     * @p n_clip vertices) with the polygon @p subject (counter-clockwise)
     * in a plane (Sutherland-Hodgman); the result in @p out (room for
     * n_subject + n_clip vertices), its vertex count returned (0 for a
     * subject folded over itself that would give more). Written for
     * AD numbers: the vertices are differentiable functions of the inputs.
     */
    template <typename Number>
    unsigned int
    clip_polygon(const std::array<Number, 2> *subject,
                 const unsigned int           n_subject,
                 const std::array<Number, 2> *clip,
                 const unsigned int           n_clip,
                 std::array<Number, 2>       *out);

    /** The signed area of a polygon in a plane (positive if
     * counter-clockwise). */
    template <typename Number>
    Number
    polygon_area(const std::array<Number, 2> *polygon, const unsigned int n);

    /** Lexicographic vertex numbers of a face in counter-clockwise order. */
    constexpr unsigned int counter_clockwise[4] = {0, 1, 3, 2};

    /** Vertex @p k of a face of @p n vertices (quadrilateral or
     * triangle) in clockwise order: a master face, counter-clockwise seen
     * from its own side, as the slave's auxiliary plane sees it. */
    inline unsigned int
    clockwise(const unsigned int n, const unsigned int k)
    {
      return n == 3 ? 2 - k : counter_clockwise[3 - k];
    }

    /** The auxiliary plane of a slave face: its centre, unit normal (out
     * of the slave), in-plane basis and the face's n vertices projected
     * onto it (in the face's order P, counter-clockwise P_ccw) with its
     * area. */
    template <typename Number>
    struct AuxiliaryPlane
    {
      Vec3<Number>          x0, n0, e1, e2;
      std::array<Number, 2> P[4], P_ccw[4];
      Number                area;
      unsigned int          n = 4;

      /** The projection of @p x along n0, in the basis e1, e2. */
      std::array<Number, 2>
      project(const Vec3<Number> &x) const
      {
        const Vec3<Number> d = x - x0;
        return std::array<Number, 2>{{dot(d, e1), dot(d, e2)}};
      }
    };

    /** The auxiliary plane of the slave face with the @p n nodes @p X
     * (lexicographic quadrilateral, or triangle): through its centre,
     * normal to a_1 x a_2 there, e1 along a_1. */
    template <typename Number>
    AuxiliaryPlane<Number>
    auxiliary_plane(const Vec3<Number> *X, const unsigned int n = 4)
    {
      const double sign_1[4] = {-1, 1, -1, 1}, sign_2[4] = {-1, -1, 1, 1};
      AuxiliaryPlane<Number> plane;
      const Number           zero(0.);
      Vec3<Number>           a_1 = {{zero, zero, zero}}, a_2 = a_1;
      plane.x0 = a_1;
      plane.n  = n;
      if (n == 3)
      {
        plane.x0 = scale(1. / 3., X[0] + X[1] + X[2]);
        a_1      = X[1] - X[0];
        a_2      = X[2] - X[0];
      }
      else
        for (unsigned int k = 0; k < 4; ++k)
        {
          plane.x0 = plane.x0 + scale(0.25, X[k]);
          a_1      = a_1 + scale(0.25 * sign_1[k], X[k]);
          a_2      = a_2 + scale(0.25 * sign_2[k], X[k]);
        }
      plane.n0 = cross(a_1, a_2);
      plane.n0 = scale(1. / norm(plane.n0), plane.n0);
      plane.e1 = scale(1. / norm(a_1), a_1);
      plane.e2 = cross(plane.n0, plane.e1);
      for (unsigned int k = 0; k < n; ++k)
        plane.P[k] = plane.project(X[k]);
      for (unsigned int k = 0; k < n; ++k)
        plane.P_ccw[k] = plane.P[n == 3 ? k : counter_clockwise[k]];
      plane.area = polygon_area(plane.P_ccw, n);
      return plane;
    }

    /**
     * Whether the master face with the @p n nodes @p Y (lexicographic
     * quadrilateral, or triangle) can carry
     * the contact of the slave face of @p plane: it faces it (unit normals
     * more than 75 degrees apart: not the side of a body above the slave)
     * and its projection overlaps the slave's in the plane (by more than
     * 1e-12 of the slave's area). The search and the element use this one
     * test.
     */
    bool
    overlaps_in_plane(const AuxiliaryPlane<double> &plane,
                      const Vec3<double>           *Y,
                      const unsigned int            n = 4);
  } // namespace internal
} // namespace tribos

#endif
