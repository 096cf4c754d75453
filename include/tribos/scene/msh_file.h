#ifndef tribos_scene_msh_file_h
#define tribos_scene_msh_file_h

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace tribos
{
  /**
   * What tribos knows of a gmsh element type: enough to check an element
   * line's node count, and to tell cells from boundary elements (by
   * dimension) and first-order meshes from curved ones (by order), without
   * gmsh.
   */
  struct MshElementType
  {
    /** gmsh's number of the type, as in the files (elm-type). */
    int type;
    /** 0 for a point, 1 for a line, 2 for a surface, 3 for a volume. */
    unsigned int dim;
    /** The nodes an element of the type lists, in gmsh's order. */
    unsigned int n_nodes;
    /** The first n_corners of them are its vertices. */
    unsigned int n_corners;
    /** The polynomial order of its geometry, 0 for a point. */
    unsigned int order;
    /** For messages, e.g. "6-node triangle". */
    const char *name;
  };

  /**
   * The type of gmsh number @p type: the types of fixed node count gmsh
   * defines up to order five (1-31, 92, 93); null for another number, so
   * that a reader can refuse it by name rather than guess its node count.
   */
  const MshElementType *
  msh_element_type(int type);



  /**
   * A malformed gmsh file. what() is "<file>:<line>: <message>", the form
   * editors and compilers use, so that the user goes straight to the line;
   * the line is 0 when the problem is the whole file (a missing section).
   */
  class MshError : public std::runtime_error
  {
  public:
    MshError(const std::string &file,
             const std::size_t  line,
             const std::string &message)
      : std::runtime_error(file + ":" + std::to_string(line) + ": " + message)
      , file_name(file)
      , line_number(line)
      , problem(message)
    {
    }

    /** The file's name, as given to read_msh_file(). */
    const std::string &
    file() const
    {
      return file_name;
    }

    /** The number (from 1) of the line that is wrong, 0 for the file. */
    std::size_t
    line() const
    {
      return line_number;
    }

    /** What is wrong and what is expected, without file and line. */
    const std::string &
    message() const
    {
      return problem;
    }

  private:
    std::string file_name;
    std::size_t line_number;
    std::string problem;
  };



  /**
   * The positions of unique 64-bit tags (gmsh's node or element tags, which
   * MSH 4.1 allows up to 2^64 - 1): a table by tag when the tags are dense,
   * as gmsh numbers them, a hash table otherwise, so that a file's size
   * bounds the memory whatever its tags.
   */
  class MshTagIndex
  {
  public:
    static constexpr std::size_t npos = static_cast<std::size_t>(-1);

    /**
     * Index @p tags by position. Returns the positions {earlier, later} of
     * the first tag that repeats (the smallest later position), or {npos,
     * npos} if the tags are unique.
     */
    std::pair<std::size_t, std::size_t>
    build(const std::vector<std::uint64_t> &tags);

    /** The position of @p tag, npos if it is none of the tags. */
    std::size_t
    find(std::uint64_t tag) const;

  private:
    std::vector<std::size_t>                       by_tag;
    std::unordered_map<std::uint64_t, std::size_t> by_sparse_tag;
  };



  /**
   * A gmsh mesh file as it is written (ASCII MSH 2.0, 2.1, 2.2 or 4.1),
   * every count, number, tag and reference checked, so that what builds a
   * triangulation from it needs to check only what tribos can mesh.
   */
  struct MshFile
  {
    static constexpr std::size_t npos = MshTagIndex::npos;

    struct Node
    {
      /** gmsh's tag of the node: 1 to 2^64 - 1. */
      std::uint64_t         tag;
      std::array<double, 3> x;
      /** The line of its coordinates, for messages. */
      std::size_t line;
    };

    struct Element
    {
      /** gmsh's tag of the element: 1 to 2^64 - 1. */
      std::uint64_t tag;
      /** gmsh's type number; msh_element_type(type) is never null. */
      int type;
      /** The dimension of the type. */
      unsigned int dim;
      /**
       * The physical group: the body id of a cell, the boundary id of a
       * face or edge; 0 if it is in none. MSH 2: the element's first tag.
       * MSH 4.1: the single physical tag of its entity in $Entities (0 for
       * a point entity in several groups: tribos does not read points).
       */
      int physical;
      /** The geometric entity (MSH 2: its second tag), 0 if not given. */
      int entity;
      /** Its nodes as positions in MshFile::nodes, in gmsh's order. */
      std::vector<std::size_t> nodes;
      /** The line that lists it, for messages. */
      std::size_t line;
    };

    /** A $PhysicalNames entry: the name of a physical group. */
    struct PhysicalName
    {
      unsigned int dim;
      int          tag;
      std::string  name;
    };

    /** The file's name, as given to read_msh_file(). */
    std::string file;
    /** 2.0, 2.1, 2.2 or 4.1. */
    double version = 0;
    /** In file order. */
    std::vector<Node> nodes;
    /** In file order. */
    std::vector<Element> elements;
    /** In file order, without the quotes. */
    std::vector<PhysicalName> physical_names;

    /** The position in nodes of the node with gmsh tag @p tag, npos if
     * the file defines none. */
    std::size_t
    node_index(const std::uint64_t tag) const
    {
      return node_tags.find(tag);
    }

    /** node_index()'s table, built by read_msh_file() (stale if nodes is
     * changed). */
    MshTagIndex node_tags;
  };



  /**
   * Read the gmsh file @p file: ASCII MSH 2.0, 2.1, 2.2 or 4.1 (the
   * versions gmsh writes by Mesh.MshFileVersion = 2.2 or 4.1). The file is
   * read a line at a time in linear time; every line is checked to have
   * exactly the numbers it should, every count against the entries listed,
   * every tag for uniqueness and every node reference for existence, so
   * that no malformed file gives a crash, a hang or a silently different
   * mesh. Throws MshError, naming the line, for the first problem.
   *
   * Where the format leaves a choice: blank lines are skipped between
   * sections and refused inside one (a line of 0 numbers); sections other
   * than $MeshFormat, $PhysicalNames, $Entities (4.1), $Nodes and $Elements
   * are skipped to their $End line; a negative physical tag is refused, not
   * taken as its absolute value (which could merge two groups); MSH 4.1
   * parametric node coordinates are checked and dropped.
   */
  MshFile
  read_msh_file(const std::string &file);
} // namespace tribos

#endif
