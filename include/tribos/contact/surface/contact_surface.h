#ifndef tribos_contact_contact_surface_h
#define tribos_contact_contact_surface_h

#include <tribos/contact/surface/face_shape.h>
#include <tribos/contact/surface/master_face.h>
#include <tribos/contact/surface/vec3.h>

#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/cell_id.h>

#include <array>
#include <set>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /**
   * The faces and nodes of a boundary part (one or more boundary ids) of a
   * Q1, P1, Q2 or P2 mesh, as seen by contact: as a slave,
   * its nodes with their tributary areas; as a master, its faces (vertex order
   * such that the normal of MasterFace points out of the body) with their
   * neighbours. Built once from the reference configuration; positions are
   * looked up per evaluation.
   *
   * Every process holds the whole surface, also on a distributed mesh:
   * each contributes the faces of its own cells and all gather them
   * (collective). Faces are numbered in the order of their cells' CellId,
   * nodes in the order they first appear, so the numbering is the same on
   * every process and for every partition.
   */
  template <int dim>
  class ContactSurface
  {
  public:
    static constexpr unsigned int n_face_nodes = MasterFace<dim>::n_nodes;

    struct Node
    {
      /** The vertex's dofs, one per component; the first names the node. */
      std::array<types::global_dof_index, dim> dofs;
      Vec3<double>                             reference{{0, 0, 0}};
      /** Tributary area (24): integral of the face shape function of the
       * node over the surface, in the reference configuration. */
      double area = 0;
      /** The element size at the node: the mean length (2D) or the
       * square root of the mean area (3D) of its faces, without the ring
       * factor 2 pi r. Inside a uniform surface this is the tributary
       * length; at the surface's edges it is not halved. */
      double size = 0;
      /** Faces this node belongs to. */
      std::vector<unsigned int> faces;
      /** At the middle of an edge of six-node triangles: the edge's
       * vertices (else -1). */
      std::array<int, 2> edge = {{-1, -1}};
    };

    struct Face
    {
      /** The face's vertices (MasterFace or TriangleFace order). */
      std::array<unsigned int, n_face_nodes> nodes;
      /** The number of vertices: n_face_nodes, or 3 for the triangle face
       * of a tetrahedron (TriangleFace; nodes[3] is then not used). */
      unsigned int n_vertices = n_face_nodes;
      /**
       * Quadratic faces: the nodes at the middles of its edges, -1 on
       * linear faces. 2D Q2 or P2: one, the face is the quadratic segment
       * through nodes[0], middles[0], nodes[1]; P2 tetrahedra: three, of
       * the edges 0-1, 1-2, 2-0 (the six-node triangle); Q2 hexahedra:
       * five, of the edges 0-1, 2-3, 0-2, 1-3 and the centre (the
       * nine-node quadrilateral). Searches and neighbourhoods still go by
       * the vertices.
       */
      std::array<int, 5> middles   = {{-1, -1, -1, -1, -1}};
      unsigned int       n_middles = 0;
      /** The number of the face's nodes: its vertices and its middles. */
      unsigned int
      n_nodes() const
      {
        return n_vertices + n_middles;
      }
      /** Node @p i of the face: the vertices, then the middles. */
      unsigned int
      node(const unsigned int i) const
      {
        return i < n_vertices ?
                 nodes[i] :
                 static_cast<unsigned int>(middles[i - n_vertices]);
      }
      /** Faces sharing at least one node with this one (itself excluded). */
      std::vector<unsigned int> neighbours;
      /**
       * Per local coordinate and side (-1, +1): whether another face of the
       * surface continues across that edge (false: the surface ends). On a
       * triangle entry 2 is xi_1 + xi_2 (Projection::clamped).
       */
      bool continues[3][2] = {{false, false}, {false, false}, {false, false}};
      /**
       * 2D only: the surface node before node 0 and after node 1 along the
       * surface (of the neighbouring faces with the same orientation), or
       * -1 where the surface ends. Used by the smoothed master normals.
       */
      int beyond[2] = {-1, -1};
      /**
       * 3D only: the vertices of the neighbouring faces that are not this
       * face's own, the ring on which the smoothed master normals of its
       * vertices depend (with its vertices, the stencil of
       * SmoothedFace).
       */
      std::vector<unsigned int> ring;
      types::material_id        body;
      /** The MPI process that owns the face's cell. */
      unsigned int owner = 0;
      /** The face's cell (a partition's weights are given per cell). */
      CellId::binary_type cell;
    };

    /**
     * With @p axisymmetric (2D, x = r) the tributary areas are those of the
     * surface of revolution, the integral of N_k 2 pi r. With
     * @p curved_geometry (the mapping of a second-order mesh's curved
     * cells; quadratic elements) the faces' middle nodes are where it puts
     * them, and the areas are integrals over the curved faces; without,
     * the faces are straight (middles at the chords' midpoints).
     */
    ContactSurface(const DoFHandler<dim>              &dof_handler,
                   const std::set<types::boundary_id> &boundary_ids,
                   const bool                          axisymmetric = false,
                   const Mapping<dim> *curved_geometry              = nullptr);

    /** The boundary ids this surface is made of. */
    const std::set<types::boundary_id> &
    boundary_ids() const
    {
      return ids;
    }

    const std::vector<Node> &
    nodes() const
    {
      return node_list;
    }

    const std::vector<Face> &
    faces() const
    {
      return face_list;
    }

    /** The kind of the surface's faces, one for all of them. */
    const FaceShape &
    shape() const
    {
      return face_shape;
    }

    /** Whether the faces are nine-node quadrilaterals (Q2 hexahedra). */
    bool
    quadratic_quadrilaterals() const
    {
      return face_shape == FaceShape::of<Quadrilateral9>();
    }

    /** Whether the faces are quadratic (Face::middles are set). */
    bool
    quadratic() const
    {
      return face_shape.degree() == 2;
    }

    /** Body ids of the cells adjacent to this surface. */
    const std::set<types::material_id> &
    bodies() const
    {
      return body_ids;
    }

  private:
    /** A face as its owner sends it: the cell, the face number, the body,
     * and per node (in MasterFace order) its dofs and reference position. */
    struct FaceRecord
    {
      CellId::binary_type cell;
      unsigned int        face       = 0;
      types::material_id  body       = 0;
      unsigned int        owner      = 0;
      unsigned int        n_vertices = n_face_nodes;
      std::array<types::global_dof_index, n_face_nodes * dim> dofs{};
      std::array<double, n_face_nodes * dim>                  x{};
      /** Quadratic faces: the dofs of the support points at the middles
       * of its edges (Face::middles), and their reference positions. */
      std::array<types::global_dof_index, 5 * dim> middle_dofs{};
      std::array<double, 5 * dim>                  middle_x{};
      unsigned int                                 n_middles = 0;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        for (auto &c : cell)
          archive &c;
        archive &face &body &owner &n_vertices;
        for (auto &d : dofs)
          archive &d;
        for (auto &v : x)
          archive &v;
        for (auto &d : middle_dofs)
          archive &d;
        for (auto &v : middle_x)
          archive &v;
        archive &n_middles;
      }
    };

    /** The oriented faces of the own cells of @p dof_handler on the
     * surface, gathered from every process in CellId order. Collective. */
    std::vector<FaceRecord>
    gather_faces(const DoFHandler<dim> &dof_handler,
                 const Mapping<dim>    *curved_geometry) const;

    /** The quadratic face @p f of @p cell (vertices in the order @p order):
     * the dofs and reference positions of its middle nodes (and the
     * nine-node quadrilateral's centre) into @p record. */
    void
    gather_middles(const typename DoFHandler<dim>::active_cell_iterator &cell,
                   const unsigned int                                    f,
                   const std::array<unsigned int, n_face_nodes>         &order,
                   const Mapping<dim> *curved_geometry,
                   FaceRecord         &record) const;

    /** The faces and their nodes from @p records. */
    void
    number_nodes(const std::vector<FaceRecord> &records);

    /** The nodes' faces, tributary areas (@p axisymmetric: of the surface
     * of revolution; curved faces on their own geometry: FaceShape::
     * integrate()) and element sizes. */
    void
    integrate_areas(const bool axisymmetric);

    /** The faces' neighbours, the edges where the surface continues, and
     * (2D) the nodes beyond a face's ends. */
    void
    find_neighbours();
    /** Whether the edge from node @p p to node @p q of @p face continues
     * into a face one level finer or coarser (across a refinement border,
     * where no other face holds both nodes). */
    bool
    continues_across_refinement(const Face        &face,
                                const unsigned int p,
                                const unsigned int q) const;

    std::set<types::boundary_id> ids;
    FaceShape                    face_shape;
    std::vector<Node>            node_list;
    std::vector<Face>            face_list;
    std::set<types::material_id> body_ids;
    bool                         is_curved = false;
  };
} // namespace tribos

#endif
