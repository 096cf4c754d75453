#ifndef tribos_scene_inp_file_h
#define tribos_scene_inp_file_h

#include <tribos/scene/msh_file.h>

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tribos
{
  /**
   * What tribos knows of an Abaqus (or CalculiX) solid element type: the
   * gmsh cell it is, where its nodes go in gmsh's order, and its faces S1,
   * S2, ... (edges in 2D), so that a deck becomes the MshFile that
   * read_msh_file() gives for the same mesh, and the triangulation builder
   * needs to know only gmsh. The tables, and the documents they are taken
   * from, are in source/scene/inp_element_types.cc.
   */
  struct InpElementType
  {
    /** The gmsh type of the cell: msh_element_type(gmsh_type) is never null. */
    int gmsh_type;
    /** 2 for plane and axisymmetric elements, 3 for solids. */
    unsigned int dim;
    /** The nodes a data line lists. */
    unsigned int n_nodes;
    /**
     * gmsh's node k is the deck's node to_gmsh[k] (both from 0). The corners
     * come first and in the same order in both numberings; the mid-edge
     * nodes differ for the tetrahedron and the 20-node hexahedron.
     */
    std::array<unsigned char, 20> to_gmsh;
    /** The number of faces, S1 to S<n_faces>. */
    unsigned int n_faces;
    /** The corners of a face: 2 (an edge in 2D), 3 or 4. */
    unsigned int n_face_corners;
    /**
     * The corners of face S<f+1>, in Abaqus's order, as positions in the
     * cell's node list (corners are the same in both numberings).
     */
    std::array<std::array<unsigned char, 4>, 6> faces;
    /** The number of edges with a middle node: 0 for a first-order cell. */
    unsigned int n_edges;
    /**
     * gmsh's edges: the middle node of edge e is gmsh's node
     * n_corners + e (second order only); how a face finds its middle nodes.
     */
    std::array<std::array<unsigned char, 2>, 12> edges;
    /** The gmsh type of a face: a boundary element (1, 8, 2, 9, 3, 16). */
    int face_type;
  };

  /**
   * The type of Abaqus element name @p name (upper case: "CPE4R", "C3D10"),
   * null if tribos does not read it: a reader refuses it by name rather than
   * guess its nodes.
   */
  const InpElementType *
  inp_element_type(std::string_view name);

  /** The element names tribos reads, for messages. */
  std::string
  inp_element_type_names();

  /**
   * The nodes of face @p face (from 0) of a cell of type @p type whose nodes
   * are @p nodes (gmsh order): its corners in Abaqus's order, then its
   * middle nodes as gmsh orders them in a boundary element (a line: the
   * middle; a triangle or quadrilateral: the middles of the edges from
   * corner 0 to 1, 1 to 2, ...).
   */
  std::vector<std::size_t>
  inp_face_nodes(const InpElementType           &type,
                 unsigned int                    face,
                 const std::vector<std::size_t> &nodes);



  /**
   * The body and boundary ids to give the sets of a deck, by name (matched
   * without regard to case, as Abaqus does). Each list empty: the default,
   * ids in order of appearance from 1 (bodies and boundaries counted
   * separately):
   *
   * - bodies: every non-empty *ELSET (or *ELEMENT ELSET=) not marked
   *   INTERNAL (the sets Abaqus/CAE writes for its surfaces), but a set
   *   that holds every cell of the deck (CalculiX's Eall, which cgx writes
   *   beside the parts) when such a set of fewer cells exists: alone, it
   *   is the one body;
   * - boundaries: every *SURFACE and *NSET (or *NODE NSET=) that holds at
   *   least one face of the mesh boundary, but a node set that holds
   *   every node of the deck (CalculiX's Nall).
   *
   * Given, only the listed sets are used, and each must exist and hold
   * cells or boundary faces. Several sets may share an id (one body of
   * two sets). A boundary name that is both a surface and a node set (Abaqus
   * keeps their names apart) is refused unless written "SURFACE:name" or
   * "NSET:name". Ids are 0 to INT_MAX.
   */
  struct InpIds
  {
    /** Element set -> body id (the cells' material id). */
    std::vector<std::pair<std::string, int>> bodies;
    /** Surface or node set -> boundary id. */
    std::vector<std::pair<std::string, int>> boundaries;
  };



  /**
   * An MshError that the ids given to read_inp_file() cause (InpIds::bodies
   * or boundaries not empty): a name that is no set of the deck, an id
   * below 0, a set given twice or holding nothing, given sets that overlap
   * with different ids or leave cells out; so that a program can name
   * where the ids came from. The deck's own problems, and those of the
   * default ids, are plain MshErrors.
   */
  class InpIdError : public MshError
  {
  public:
    InpIdError(const std::string &file,
               const std::size_t  line,
               const std::string &message,
               const bool         boundaries)
      : MshError(file, line, message)
      , of_boundaries(boundaries)
    {
    }

    /** Whether InpIds::boundaries caused it (else InpIds::bodies). */
    bool
    boundaries() const
    {
      return of_boundaries;
    }

  private:
    bool of_boundaries;
  };

  /**
   * Read the Abaqus or CalculiX input deck @p file into what read_msh_file()
   * gives for the same mesh in a gmsh file, so that it builds a
   * triangulation the same way: the nodes; the cells in gmsh's node order
   * with the gmsh type, physical = body id; then one boundary element (gmsh
   * line, triangle or quadrilateral of the cells' order) per face that a
   * boundary set holds, physical = boundary id; entity 0; physical_names
   * the sets' names (dimension: the cells' for bodies, one less for
   * boundaries; the names of sets of one id joined by ", "; a body named
   * with id 0 gives a name of tag 0, which a gmsh file cannot have), so
   * that the ids given by default can be reported. version is 0 (nothing
   * reads it). A boundary element's tag is the largest element label plus
   * 1, 2, ...; its line that of the *SURFACE data line or the *NSET
   * keyword.
   *
   * Read: *NODE (NSET=), *ELEMENT (TYPE=, ELSET=; a data line that ends
   * with a comma continues on the next), *ELSET and *NSET (labels and set
   * names, or GENERATE: first, last[, step]; a repeated name adds to the
   * set), *SURFACE (TYPE=ELEMENT: 'element or element set, S<n>';
   * TYPE=NODE: 'node or node set'), *INCLUDE (INPUT= relative to the
   * including file; textual, so its data lines may continue a keyword of
   * the including file). Keywords and parameters without regard to case and
   * blanks; '**' comment lines and blank lines skipped; every other keyword
   * (*HEADING, *MATERIAL, *STEP, *BOUNDARY, ...) skipped with its data
   * lines. Refused by name, as what would be misread if skipped: parts and
   * instances (*PART, *ASSEMBLY, *INSTANCE, INSTANCE=), what generates or
   * moves nodes or elements (*NGEN, *NFILL, *NCOPY, *NMAP, *ELGEN,
   * *ELCOPY, *SYSTEM, *NODE SYSTEM= other than R), data in other files
   * (INPUT= but on *INCLUDE), *NSET ELSET=, *SURFACE TYPE= other than
   * ELEMENT and NODE, C3D27 and every element type but those of
   * inp_element_type().
   *
   * Rules: labels are integers from 1 to 2^64 - 1 and unique; coordinates
   * finite (an empty field is 0, as in Abaqus, a z absent is 0); a set, a
   * surface or an element refers only to what is defined above it (so that
   * no reference can be cyclic); the cells are all 2D or all 3D. A body is
   * a set of cells: a cell in two body sets of different ids, or in none
   * while the deck has body sets, is refused (all cells are body 0 when
   * there is no body set). A boundary face is a face of one cell only: a
   * *SURFACE face shared by two cells is refused; a node set holds the
   * boundary faces all of whose nodes (corners and middles) are in it; a
   * face in two boundary sets of different ids is refused. A 2D deck off
   * the x-y plane, cells of mixed kind or order, and degenerate cells are
   * left to the triangulation builder, as for a gmsh file.
   *
   * Node::line and Element::line are lines of the file that defines them,
   * which is @p file unless the deck uses *INCLUDE (MshFile has one file
   * name). Throws MshError naming the file and line (0 for the whole deck
   * or for @p ids) of the first problem, an InpIdError if @p ids caused
   * it. The work is linear in the deck's size (hash tables; the members
   * that sets copy from sets are bounded by 64 per node and element), but
   * for sorting each node set's faces.
   */
  MshFile
  read_inp_file(const std::string &file, const InpIds &ids = InpIds());
} // namespace tribos

#endif
