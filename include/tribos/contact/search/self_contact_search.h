#ifndef tribos_contact_self_contact_search_h
#define tribos_contact_self_contact_search_h

#include <tribos/contact/contact_pair.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

namespace tribos
{
  /**
   * What every discretization of a self-contact pair (the slave surface is
   * its own master) needs from the search: the faces a node may never
   * touch (its own and those sharing a node with them: its neighbourhood,
   * reference topology) and how far to look for the others. The tree's
   * closest face is always one of the node's own, so the faces are taken
   * from a box query (ContactSearch::faces_near()) whose reach starts at
   * twice the largest element size and doubles until an admissible face
   * is found or it passes the first reach plus twice the way the node went
   * in the increment (an increment that carries a node through an
   * opposite face it had not touched must still find that face), never
   * beyond twice the surface's extent or Contact/Search distance.
   * Which faces are admissible (facing the node, not the far side of its
   * own body) is the discretization's: a node's normal for node to
   * segment, a slave face's for mortar.
   */
  template <int dim>
  class SelfContactSearch
  {
  public:
    /** The cosine of the unit normals of two neighbouring faces below which
     * they meet across a crease (154 degrees apart), see own(). */
    static constexpr double crease = -0.9;

    /**
     * For a self pair: each node's neighbourhood and the reach; refuses a
     * surface whose every face is in every node's neighbourhood (nothing
     * can touch). For other pairs nothing (active() is false).
     */
    void
    initialize(const ContactPair<dim> &pair, const double search_distance);

    /** The warning of initialize() if no node of the surface faces a face
     * of it, in front of it, within a finite Search distance (reference
     * configuration): the surface cannot touch itself unless it folds
     * closer than that. Empty if none. */
    std::vector<std::string>
    warnings() const
    {
      return warning.empty() ? std::vector<std::string>() :
                               std::vector<std::string>(1, warning);
    }

    /** Whether the pair is a self pair (initialize() found one). */
    bool
    active() const
    {
      return !neighbourhood.empty();
    }

    /**
     * Whether face @p f is one of node @p k's own faces or shares a node
     * with one. Node to segment never pairs a node with such a face; mortar
     * pairs a slave face with a neighbour across a crease (the cosine of
     * their unit normals below #crease), where a fold closes down to its
     * tip (the quadratic ring's fold pinched its tip shut through the
     * neighbours it could not see, and its elements inverted).
     */
    bool
    own(const unsigned int k, const unsigned int f) const
    {
      return std::binary_search(neighbourhood[k].begin(),
                                neighbourhood[k].end(),
                                f);
    }

    /** Whether face @p f is one of node @p k's own faces. */
    bool
    of_node(const ContactPair<dim> &pair,
            const unsigned int      k,
            const unsigned int      f) const
    {
      const auto &faces = pair.slave->nodes()[k].faces;
      return std::find(faces.begin(), faces.end(), f) != faces.end();
    }

    /** The farthest any node looks (twice the surface's extent, or Search
     * distance). */
    double
    maximum_reach() const
    {
      return largest;
    }

    /**
     * The closest face to @p x of those @p admissible(f, distance) accepts
     * (setting their distance; a face not known is never asked, the node's
     * neighbourhood is: see own()), looked for within the reach, then twice as
     * far until one is found or the reach passes the first one plus twice
     * @p motion (the way the node went in the increment). -1 if none;
     * @p distance gets the closest one's.
     */
    template <class Admissible>
    int
    closest(const ContactPair<dim> &pair,
            const unsigned int      k,
            const Vec3<double>     &x,
            const double            motion,
            const Admissible       &admissible,
            double                 &distance) const
    {
      const double farthest = std::min(largest, reach + 2 * motion);
      int          best     = -1;
      distance              = std::numeric_limits<double>::max();
      for (double r = std::min(reach, farthest); best < 0;)
      {
        for (const unsigned int f : pair.search.faces_near(x, r))
        {
          double d;
          if (pair.face_known[f] && admissible(f, d) && d <= r && d < distance)
          {
            best     = f;
            distance = d;
          }
        }
        if (r >= farthest)
          break;
        r = std::min(2 * r, farthest);
      }
      return best;
    }

  private:
    /** The check behind warnings(): O(nodes x faces), with a finite Search
     * distance only. */
    void
    check_reach(const ContactPair<dim> &pair, const double distance);

    /** Per node, the faces that share a node with its faces (sorted; its
     * own faces included). Empty for other pairs. */
    std::vector<std::vector<unsigned int>> neighbourhood;
    /** How far from a node faces are looked for first, and at most. */
    double reach   = 0;
    double largest = 0;
    /** See warnings(). */
    std::string warning;
  };
} // namespace tribos

#endif
