#ifndef tribos_contact_element_mortar_element_3d_internal_h
#define tribos_contact_element_mortar_element_3d_internal_h

/**
 * The faces of the 3D mortar element (Mortar3D) as its parts see them,
 * shared by mortar_element_3d.cc (the overlaps and their integrals) and
 * mortar_element_3d_dual.cc (the dual functions); not an interface.
 */

#include <tribos/contact/element/mortar_integrals.h>
#include <tribos/contact/surface/face_kinds.h>

#include <array>

namespace tribos
{
  namespace internal::Mortar3DImplementation
  {
    using AD = ContactAD;

    /** The most nodes of a face (the nine-node quadrilateral). */
    constexpr unsigned int max_face_nodes = MortarFace3D::max_nodes;

    template <typename Number>
    using Plane = internal::AuxiliaryPlane<Number>;

    /** Shape functions of a face of @p n nodes: MasterFace<3> (4),
     * TriangleFace (3), the quadratic triangle (6: vertices, then the
     * middles of the edges 0-1, 1-2, 2-0) or the biquadratic
     * quadrilateral (9: MortarFace3D's order); no derivatives of the
     * quadratic ones. */
    template <typename Number>
    void
    face_shape(const unsigned int n,
               const Number      *xi,
               Number            *N,
               Number (*dN)[2])
    {
      if (n == 3)
        Triangle3::shape(xi, N, dN);
      else if (n == 4)
        Quadrilateral4::shape(xi, N, dN);
      else if (n == 9)
        Quadrilateral9::values(xi, N);
      else
        Triangle6::values(xi, N);
    }

    /**
     * A flat piece of a face, what the overlaps are clipped and integrated
     * on: a linear face is one piece, itself; a quadratic triangle is four,
     * the triangles of its vertices and edge middles (Popp et al.'s
     * integration on linear sub-elements); a nine-node quadrilateral four
     * bilinear quadrilaterals, each with a vertex, two edge middles and
     * the centre. The piece's n nodes as positions
     * in its face and their coordinates in the face's map.
     */
    struct Piece
    {
      unsigned int n;
      unsigned int node[4];
      double       xi[4][2];
    };

    /** The face coordinates of the point with coordinates @p x in
     * @p piece. */
    template <typename Number>
    void
    face_coordinates(const Piece &piece, const Number *x, Number *xi)
    {
      Number N[4], dN[4][2];
      face_shape(piece.n, x, N, dN);
      xi[0] = xi[1] = 0.;
      for (unsigned int v = 0; v < piece.n; ++v)
        for (unsigned int c = 0; c < 2; ++c)
          xi[c] += N[v] * piece.xi[v][c];
    }

    /** The 7-point rule of degree 5 on a triangle (Dunavant): barycentric
     * coordinates and weights (summing to 1). */
    struct TrianglePoint
    {
      double l[3], weight;
    };
    constexpr double a_1                     = 0.0597158717897698204929,
                     b_1                     = 0.4701420641051150897536,
                     w_1                     = 0.1323941527885061807294,
                     a_2                     = 0.7974269853530873223564,
                     b_2                     = 0.1012865073234563388218,
                     w_2                     = 0.1259391805448271525956;
    constexpr TrianglePoint triangle_rule[7] = {{{1. / 3., 1. / 3., 1. / 3.},
                                                 0.225},
                                                {{a_1, b_1, b_1}, w_1},
                                                {{b_1, a_1, b_1}, w_1},
                                                {{b_1, b_1, a_1}, w_1},
                                                {{a_2, b_2, b_2}, w_2},
                                                {{b_2, a_2, b_2}, w_2},
                                                {{b_2, b_2, a_2}, w_2}};

    /**
     * The row @p a (coefficients of the face's functions N) of the
     * functions slave face @p f of @p input carries in Phi = A Ntilde
     * (Ntilde = T N the modified basis, A = D_e M_e^-1 of its mass matrix
     * M_e = int Ntilde Ntilde^T over the face's pieces in their planes
     * @p planes, D_e its row sums), blended with Ntilde by @p theta as in
     * 2D, summed with their weights: node j's row, and those of the
     * hanging nodes it carries.
     */
    void
    carried_row(const MortarInput3D &input,
                const unsigned int   f,
                const Piece         *pieces,
                const unsigned int   n_pieces,
                const Plane<AD>     *planes,
                const AD            &theta,
                AD                  *a);
  } // namespace internal::Mortar3DImplementation
} // namespace tribos

#endif
