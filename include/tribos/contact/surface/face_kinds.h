#ifndef tribos_contact_surface_face_kinds_h
#define tribos_contact_surface_face_kinds_h

#include <tribos/contact/surface/master_face.h>

#include <type_traits>

namespace tribos
{
  /**
   * @name The six kinds of contact face
   *
   * A mesh has one kind of cell and one polynomial degree, so each contact
   * surface has one kind of face: the 2- or 3-node segment in 2D (Q1/P1,
   * Q2/P2 cells), the 4-node quadrilateral, 3-node triangle, 6-node
   * triangle or 9-node quadrilateral in 3D (Q1 hexahedra, P1 and P2
   * tetrahedra, Q2 hexahedra). Each kind is an empty struct whose static
   * members are what the code needs to know about it: counts, shape
   * functions (templates on the number type, so that the contact elements'
   * automatic differentiation inlines them), the local numbering of its
   * edges, middles and pieces. FaceShape holds one of them at run time and
   * is the one place where a kind is chosen; a piece of code that handles
   * faces by kind visits it, and the compiler then asks for every kind.
   *
   * The node order: the vertices (in the order of MasterFace or
   * TriangleFace), then the middles of the edges, then the centre of a
   * nine-node quadrilateral. Local coordinates: [-1, 1]^(dim-1) on
   * segments and quadrilaterals, the unit triangle on triangles.
   * @{
   */

  /**
   * The linear segment of a Q1 or P1 mesh in 2D: MasterFace<2>.
   */
  struct Segment2 : MasterFace<2>
  {
    /** The dimension of the mesh whose faces this kind is. */
    static constexpr int          dim        = 2;
    static constexpr unsigned int n_vertices = 2;
    static constexpr unsigned int n_middles  = 0;
    static constexpr unsigned int degree     = 1;
    /** The linear face on the same vertices (orientation, search). */
    using Linear = Segment2;
    /** Local coordinates of the nodes. */
    static constexpr double support_points[2][2] = {{-1, 0}, {1, 0}};
    /** Where the orientation of a face is taken. */
    static constexpr double centre[2] = {0, 0};
    /** The two vertices swapped to turn the normal over. */
    static constexpr unsigned int flip[2] = {0, 1};
    /**
     * The nodes on each edge, per local coordinate and side (-1, +1) as in
     * Projection::clamped, -1 where there are none: a segment's ends.
     */
    static constexpr unsigned int n_edge_coordinates  = 1;
    static constexpr int          edge_nodes[1][2][2] = {{{0, -1}, {1, -1}}};
    /** Closest-point projection of @p point onto the face (tribos::
     * project()). */
    static Projection
    project(const Vec3<double> &point,
            const Vec3<double> *x,
            const bool          clamp = true)
    {
      return ::tribos::project<2>(point, x, clamp);
    }

    template <typename Number>
    static void
    values(const Number *xi, Number *N)
    {
      Number dN[2][2];
      shape(xi, N, dN);
    }
  };



  /**
   * The bilinear quadrilateral of a Q1 hexahedron: MasterFace<3>.
   */
  struct Quadrilateral4 : MasterFace<3>
  {
    static constexpr int          dim                  = 3;
    static constexpr unsigned int n_vertices           = 4;
    static constexpr unsigned int n_middles            = 0;
    static constexpr unsigned int degree               = 1;
    using Linear                                       = Quadrilateral4;
    static constexpr double       support_points[4][2] = {{-1, -1},
                                                          {1, -1},
                                                          {-1, 1},
                                                          {1, 1}};
    static constexpr double       centre[2]            = {0, 0};
    static constexpr unsigned int flip[2]              = {1, 2};
    static constexpr unsigned int n_edge_coordinates   = 2;
    static constexpr int          edge_nodes[2][2][2]  = {{{0, 2}, {1, 3}},
                                                          {{0, 1}, {2, 3}}};
    /** The triangles by which the contact search bounds the face: the
     * lexicographic quadrilateral 0 1 / 2 3 as (0, 1, 3) and (0, 3, 2). */
    static constexpr unsigned int search_triangles[2][3] = {{0, 1, 3},
                                                            {0, 3, 2}};

    static Projection
    project(const Vec3<double> &point,
            const Vec3<double> *x,
            const bool          clamp = true)
    {
      return ::tribos::project<3>(point, x, clamp);
    }

    /** How far @p xi lies outside the face (0 inside), in the units of
     * within()'s band. */
    static double
    outside(const double *xi)
    {
      return std::max({0., std::abs(xi[0]) - 1., std::abs(xi[1]) - 1.});
    }

    template <typename Number>
    static void
    values(const Number *xi, Number *N)
    {
      Number dN[4][2];
      shape(xi, N, dN);
    }
  };



  /**
   * The linear triangle of a P1 tetrahedron: TriangleFace. Its edges
   * xi_1 = 0, xi_2 = 0 (side -1) and xi_1 + xi_2 = 1 (side +1).
   */
  struct Triangle3 : TriangleFace
  {
    static constexpr int          dim                = 3;
    static constexpr unsigned int n_vertices         = 3;
    static constexpr unsigned int n_middles          = 0;
    static constexpr unsigned int degree             = 1;
    using Linear                                     = Triangle3;
    static constexpr double support_points[3][2]     = {{0, 0}, {1, 0}, {0, 1}};
    static constexpr double centre[2]                = {1. / 3, 1. / 3};
    static constexpr unsigned int flip[2]            = {1, 2};
    static constexpr unsigned int n_edge_coordinates = 3;
    static constexpr int          edge_nodes[3][2][2]    = {{{0, 2}, {-1, -1}},
                                                            {{0, 1}, {-1, -1}},
                                                            {{-1, -1}, {1, 2}}};
    static constexpr unsigned int search_triangles[1][3] = {{0, 1, 2}};

    static Projection
    project(const Vec3<double> &point,
            const Vec3<double> *x,
            const bool          clamp = true)
    {
      return project_triangle(point, x, clamp);
    }

    /** As Quadrilateral4::outside(): a triangle's coordinates span 1. */
    static double
    outside(const double *xi)
    {
      return 2 * std::max({0., -xi[0], -xi[1], xi[0] + xi[1] - 1.});
    }

    template <typename Number>
    static void
    values(const Number *xi, Number *N)
    {
      Number dN[3][2];
      shape(xi, N, dN);
    }
  };



  /**
   * The quadratic segment of a Q2 or P2 mesh in 2D: its ends (xi = -1, +1),
   * then its middle (xi = 0).
   */
  struct Segment3
  {
    static constexpr int          dim            = 2;
    static constexpr unsigned int n_coords       = 1;
    static constexpr unsigned int n_vertices     = 2;
    static constexpr unsigned int n_middles      = 1;
    static constexpr unsigned int n_nodes        = 3;
    static constexpr unsigned int degree         = 2;
    using Linear                                 = Segment2;
    static constexpr double support_points[3][2] = {{-1, 0}, {1, 0}, {0, 0}};
    /** The vertices a-b of the edges whose middles are nodes n_vertices,
     * ...: in 2D the face itself. */
    static constexpr unsigned int middle_edges[1][2] = {{0, 1}};
    /** Whether the face's centre is a node (after the edges' middles). */
    static constexpr bool has_centre = false;
    /** Whether rigid contact sees the middles as virtual points between
     * their edge's vertices (Node::edge). */
    static constexpr bool middles_as_virtual_points = false;

    template <typename Number>
    static void
    values(const Number *xi, Number *N)
    {
      Number dN[3];
      quadratic_segment_shape(xi[0], N, dN);
    }

    template <typename Number>
    static void
    shape(const Number *xi, Number *N, Number (*dN)[2])
    {
      Number dL[3];
      quadratic_segment_shape(xi[0], N, dL);
      for (unsigned int i = 0; i < 3; ++i)
        dN[i][0] = dL[i];
    }
  };



  /**
   * The six-node triangle of a P2 tetrahedron: the vertices, then the
   * middles of the edges 0-1, 1-2, 2-0. Contact works in its modified basis
   * (TriangleFace::modified_basis_alpha).
   */
  struct Triangle6
  {
    static constexpr int          dim        = 3;
    static constexpr unsigned int n_coords   = 2;
    static constexpr unsigned int n_vertices = 3;
    static constexpr unsigned int n_middles  = 3;
    static constexpr unsigned int n_nodes    = 6;
    static constexpr unsigned int degree     = 2;
    using Linear                             = Triangle3;
    static constexpr double support_points[6][2] =
      {{0, 0}, {1, 0}, {0, 1}, {.5, 0}, {.5, .5}, {0, .5}};
    static constexpr unsigned int middle_edges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
    static constexpr bool         has_centre         = false;
    static constexpr bool         middles_as_virtual_points = true;

    template <typename Number>
    static void
    values(const Number *xi, Number *N)
    {
      const Number l[3] = {1. - xi[0] - xi[1], xi[0], xi[1]};
      for (unsigned int v = 0; v < 3; ++v)
      {
        N[v]     = l[v] * (2. * l[v] - 1.);
        N[3 + v] = 4. * l[v] * l[(v + 1) % 3];
      }
    }

    template <typename Number>
    static void
    shape(const Number *xi, Number *N, Number (*dN)[2])
    {
      const Number l[3]     = {1. - xi[0] - xi[1], xi[0], xi[1]};
      const double dl[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
      for (unsigned int v = 0; v < 3; ++v)
      {
        const unsigned int w = (v + 1) % 3;
        N[v]                 = l[v] * (2. * l[v] - 1.);
        N[3 + v]             = 4. * l[v] * l[w];
        for (unsigned int k = 0; k < 2; ++k)
        {
          dN[v][k]     = (4. * l[v] - 1.) * dl[v][k];
          dN[3 + v][k] = 4. * (dl[v][k] * l[w] + l[v] * dl[w][k]);
        }
      }
    }
  };



  /**
   * The nine-node quadrilateral of a Q2 hexahedron: the vertices
   * (lexicographic), the middles of the edges 0-1, 2-3, 0-2, 1-3, the
   * centre. Node i is the product of the quadratic segment's functions
   * at_1[i] in xi_1 and at_2[i] in xi_2 (0: -1, 1: +1, 2: the middle).
   */
  struct Quadrilateral9
  {
    static constexpr int          dim                       = 3;
    static constexpr unsigned int n_coords                  = 2;
    static constexpr unsigned int n_vertices                = 4;
    static constexpr unsigned int n_middles                 = 5;
    static constexpr unsigned int n_nodes                   = 9;
    static constexpr unsigned int degree                    = 2;
    using Linear                                            = Quadrilateral4;
    static constexpr double       support_points[9][2]      = {{-1, -1},
                                                               {1, -1},
                                                               {-1, 1},
                                                               {1, 1},
                                                               {0, -1},
                                                               {0, 1},
                                                               {-1, 0},
                                                               {1, 0},
                                                               {0, 0}};
    static constexpr unsigned int middle_edges[4][2]        = {{0, 1},
                                                               {2, 3},
                                                               {0, 2},
                                                               {1, 3}};
    static constexpr bool         has_centre                = true;
    static constexpr bool         middles_as_virtual_points = false;
    static constexpr unsigned int at_1[9] = {0, 1, 0, 1, 2, 2, 0, 1, 2},
                                  at_2[9] = {0, 0, 1, 1, 0, 1, 2, 2, 2};

    template <typename Number>
    static void
    values(const Number *xi, Number *N)
    {
      Number l[2][3], dl[3];
      for (unsigned int d = 0; d < 2; ++d)
        quadratic_segment_shape(xi[d], l[d], dl);
      for (unsigned int i = 0; i < 9; ++i)
        N[i] = l[0][at_1[i]] * l[1][at_2[i]];
    }

    template <typename Number>
    static void
    shape(const Number *xi, Number *N, Number (*dN)[2])
    {
      Number L1[3], dL1[3], L2[3], dL2[3];
      quadratic_segment_shape(xi[0], L1, dL1);
      quadratic_segment_shape(xi[1], L2, dL2);
      for (unsigned int i = 0; i < 9; ++i)
      {
        N[i]     = L1[at_1[i]] * L2[at_2[i]];
        dN[i][0] = dL1[at_1[i]] * L2[at_2[i]];
        dN[i][1] = L1[at_1[i]] * dL2[at_2[i]];
      }
    }
  };

  /** The linear face of a hypercube mesh of dimension @p dim. */
  template <int dim>
  using LinearFace = std::conditional_t<dim == 2, Segment2, Quadrilateral4>;

  /** @} */
} // namespace tribos

#endif
