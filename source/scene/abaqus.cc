/**
 * Scene "abaqus": the mesh of an Abaqus or CalculiX input deck
 * (read_inp_file()), its element sets the bodies, its surfaces and node
 * sets the boundaries, built into the triangulation by the gmsh scene's
 * reader (GmshSecondOrder), first- or second-order.
 */

#include <tribos/base/text.h>
#include <tribos/scene/gmsh_second_order.h>
#include <tribos/scene/inp_file.h>
#include <tribos/scene/scene.h>

#include <algorithm>
#include <climits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace tribos
{
  namespace
  {
    /**
     * The sets of the parameter Scene/@p entry = @p text: items 'set : id'
     * separated by commas (the id after the last colon, so that a name may
     * be SURFACE:name or NSET:name), each id at least @p smallest
     * (@p why_smallest says why, for the message). @p kinds and
     * @p example for the messages.
     */
    std::vector<std::pair<std::string, int>>
    parse_sets(const std::string &text,
               const std::string &entry,
               const std::string &kinds,
               const std::string &example,
               const int          smallest,
               const std::string &why_smallest)
    {
      std::vector<std::pair<std::string, int>> sets;
      for (const std::string &item : Text::split_top_level(text, ','))
      {
        const std::size_t colon = item.rfind(':');
        const bool        has   = colon != std::string::npos;
        const std::string name  = has ? Text::trim(item.substr(0, colon)) : "";
        const std::string id    = has ? Text::trim(item.substr(colon + 1)) : "";
        // At most 10 digits: std::stoll cannot overflow.
        const bool digits =
          !id.empty() && id.size() <= 10 &&
          id.find_first_not_of("0123456789") == std::string::npos;
        AssertThrow(!name.empty() && digits && std::stoll(id) <= INT_MAX,
                    ExcMessage(
                      "Parameter <Scene/" + entry + "> = <" +
                      Text::abbreviate(text) + ">: the item <" +
                      Text::abbreviate(item) +
                      "> does not read 'set : id'. Each item, separated by "
                      "commas, is the name of " +
                      kinds +
                      " of the deck, a colon and its id, an integer "
                      "from " +
                      std::to_string(smallest) + " to " +
                      std::to_string(INT_MAX) + ", e.g. '" + example +
                      "'; empty, the deck's sets get ids by default (the "
                      "README's scene abaqus)."));
        sets.emplace_back(name, int(std::stoll(id)));
        AssertThrow(sets.back().second >= smallest,
                    ExcMessage("Parameter <Scene/" + entry + "> = <" +
                               Text::abbreviate(text) + ">: the set <" + name +
                               "> is given id " + id + ", " + why_smallest +
                               ". Give it an id from " +
                               std::to_string(smallest) + " to " +
                               std::to_string(INT_MAX) + "."));
      }
      return sets;
    }



    class AbaqusScene;

    template <int dim>
    void
    build_deck(const AbaqusScene  &scene,
               const unsigned int  refinement,
               Triangulation<dim> &tria,
               CurvedCells<dim>   *curved);



    /** Scene "abaqus": an input deck (Scene/Input deck, Body sets,
     * Boundary sets). */
    class AbaqusScene : public SceneInBothDimensions<AbaqusScene>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry(
          "Input deck",
          "",
          Patterns::Anything(),
          "Abaqus or CalculiX .inp file for Name = abaqus: its *NODE and "
          "*ELEMENT data (plane, axisymmetric and solid elements, first or "
          "second order) are the mesh, its element sets the bodies, its "
          "surfaces and node sets the boundaries; materials, steps and "
          "loads are skipped (set them here).");
        prm.declare_entry(
          "Body sets",
          "",
          Patterns::Anything(),
          "Name = abaqus: element sets and their body ids, e.g. 'PLATE : 1, "
          "BLOCK : 2'. Empty: every element set (not INTERNAL) is a body, "
          "ids 1, 2, ... in the deck's order (a set of every element, such "
          "as CalculiX's Eall, only if there is no set of fewer).");
        prm.declare_entry(
          "Boundary sets",
          "",
          Patterns::Anything(),
          "Name = abaqus: surfaces and node sets and their boundary ids, "
          "e.g. 'BOTTOM : 1, TOP : 2' (a node set holds the boundary faces "
          "all of whose nodes it holds; SURFACE:name or NSET:name where a "
          "surface and a node set share a name). Empty: every surface and "
          "node set that holds boundary faces, ids 1, 2, ... in the deck's "
          "order (but a set of every node, such as CalculiX's Nall). Ids "
          "from 1: the boundary faces in no set have id 0.");
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        deck_file     = prm.get("Input deck");
        body_sets     = prm.get("Body sets");
        boundary_sets = prm.get("Boundary sets");
        ids.bodies    = parse_sets(body_sets,
                                "Body sets",
                                "an element set",
                                "PLATE : 1, BLOCK : 2",
                                0,
                                "");
        // Boundary id 0 is the faces in no set (the deck's untagged faces,
        // as a gmsh mesh's, whose physical tags start at 1): a set given 0
        // would merge with them, and a condition on it would move the
        // bodies' other sides too.
        ids.boundaries = parse_sets(
          boundary_sets,
          "Boundary sets",
          "a surface or a node set",
          "BOTTOM : 1, TOP : 2",
          1,
          "the id of the boundary faces that are in no boundary set "
          "(untagged, as in a gmsh mesh): a condition or contact pair on it "
          "would take those faces too");
        deck.reset();
      }

      template <int dim>
      void
      build(const unsigned int refinement, Triangulation<dim> &tria) const
      {
        build_deck<dim>(*this, refinement, tria, nullptr);
      }

      void
      create_curved(const unsigned int refinement,
                    Triangulation<2>  &tria,
                    CurvedCells<2>    &curved) const override
      {
        build_deck(*this, refinement, tria, &curved);
      }

      void
      create_curved(const unsigned int refinement,
                    Triangulation<3>  &tria,
                    CurvedCells<3>    &curved) const override
      {
        build_deck(*this, refinement, tria, &curved);
      }

      unsigned int
      mesh_order(const unsigned int dim) const override
      {
        return dim == 2 ? GmshSecondOrder::order<2>(mesh(), deck_name()) :
                          GmshSecondOrder::order<3>(mesh(), deck_name());
      }

      std::vector<std::string>
      describe() const override;

      std::string
      mesh_source() const override
      {
        return deck_name();
      }

      /** What the messages about the deck start with. */
      std::string
      deck_name() const
      {
        return "Parameter <Scene/Input deck> = <" + deck_file + ">";
      }

      /** The deck as a gmsh file of its mesh (read once). */
      const MshFile &
      mesh() const;

    private:
      std::string deck_file, body_sets, boundary_sets;
      InpIds      ids;
      /** The deck read: the scene is built more than once (coarse and
       * refined, and its order asked). */
      mutable std::shared_ptr<const MshFile> deck;
    };



    const MshFile &
    AbaqusScene::mesh() const
    {
      AssertThrow(!deck_file.empty(),
                  ExcMessage("Parameter <Scene/Input deck> is empty: Scene/"
                             "Name = abaqus needs an Abaqus or CalculiX .inp "
                             "file."));
      if (deck)
        return *deck;
      try
      {
        deck = std::make_shared<const MshFile>(read_inp_file(deck_file, ids));
      }
      catch (const InpIdError &error)
      {
        const bool of_boundaries = error.boundaries();
        AssertThrow(
          false,
          ExcMessage(
            "Parameter <Scene/" +
            std::string(of_boundaries ? "Boundary sets" : "Body sets") +
            "> = <" +
            Text::abbreviate(of_boundaries ? boundary_sets : body_sets) +
            "> of the deck <" + deck_file + ">: " + error.what()));
      }
      catch (const MshError &error)
      {
        AssertThrow(false, ExcMessage(deck_name() + ": " + error.what()));
      }
      return *deck;
    }



    std::vector<std::string>
    AbaqusScene::describe() const
    {
      // The ids by set, as Body sets and Boundary sets would give them
      // (sets of one id have one physical name, joined by ", ").
      const MshFile &file     = mesh();
      unsigned int   cell_dim = 0;
      for (const auto &e : file.elements)
        cell_dim = std::max(cell_dim, e.dim);
      std::string bodies, boundaries;
      for (const auto &group : file.physical_names)
        for (const std::string &set : Text::split_top_level(group.name, ','))
        {
          std::string &list = group.dim == cell_dim ? bodies : boundaries;
          list += (list.empty() ? "" : ", ") + set + " : " +
                  std::to_string(group.tag);
        }
      const std::string deck_of = "Input deck <" + deck_file + ">: ";
      return {deck_of + "Body sets = " +
                (bodies.empty() ? "none (every cell is body 0)" : bodies) +
                (ids.bodies.empty() ? " (by default)" : ""),
              deck_of + "Boundary sets = " +
                (boundaries.empty() ? "none" : boundaries) +
                (ids.boundaries.empty() ? " (by default)" : "")};
    }



    template <int dim>
    void
    build_deck(const AbaqusScene  &scene,
               const unsigned int  refinement,
               Triangulation<dim> &tria,
               CurvedCells<dim>   *curved)
    {
      std::vector<std::vector<Point<dim>>> coarse;
      const bool                           second_order =
        GmshSecondOrder::read(scene.mesh(), scene.deck_name(), tria, coarse);
      AssertThrow(tria.all_reference_cells_are_hyper_cube() ||
                    tria.all_reference_cells_are_simplex(),
                  ExcMessage(scene.deck_name() +
                             ": the deck mixes triangles or tetrahedra with "
                             "quadrilaterals or hexahedra. tribos takes one "
                             "kind of cell per mesh (the finite element "
                             "follows the kind): triangles or tetrahedra "
                             "only (CPE3, CPE6, C3D4, C3D10, ...) or "
                             "quadrilaterals or hexahedra only (CPE4, CPE8, "
                             "C3D8, C3D20, ...)."));
      if (second_order && curved != nullptr)
        curved->support_points =
          GmshSecondOrder::refine(tria, refinement, coarse);
      else
        tria.refine_global(refinement);
    }
  } // namespace

  const SceneRegistration abaqus_scene = register_scene<AbaqusScene>("abaqus");
} // namespace tribos
