#include <tribos/base/text.h>
#include <tribos/contact/discretization/discretization_method.h>
#include <tribos/contact/enforcement/enforcement_method.h>
#include <tribos/parameters/contact.h>
#include <tribos/parameters/contact_pair.h>

#include <cmath>
#include <cstdlib>
#include <optional>
#include <set>

namespace tribos
{
  namespace Parameters
  {
    std::string
    parse_method(const std::string &text, const std::string &entry)
    {
      AssertThrow(enforcement_registry().find(text) != nullptr,
                  dealii::ExcMessage("Parameter <" + entry + ">: method <" +
                                     text + "> unknown. Allowed: " +
                                     enforcement_registry().join(", ") + "."));
      return text;
    }



    PenaltyValue
    PenaltyValue::parse(const std::string &input, const std::string &entry)
    {
      PenaltyValue      result;
      const std::string text = Text::trim(input);
      if (text.empty())
        return result;
      result.given = true;

      // Without blanks: '100 * E / h' reads as '100*E/h'.
      std::string compact;
      for (const char c : text)
        if (c != ' ' && c != '\t')
          compact += c;
      std::string number    = compact;
      const auto  ends_with = [&compact](const std::string &tail)
      {
        return compact.size() >= tail.size() &&
               compact.compare(compact.size() - tail.size(),
                               tail.size(),
                               tail) == 0;
      };
      const std::string allowed =
        "Write 'k*E/h' (k times the pair's contact modulus E over the "
        "slave node's element size h, free of the length unit; e.g. "
        "'100*E/h') or an absolute value in stress per length (e.g. "
        "'1e5').";
      if (compact == "E/h")
      {
        result.per_node = true;
        number          = "1";
      }
      else if (ends_with("*E/h"))
      {
        result.per_node = true;
        number          = compact.substr(0, compact.size() - 4);
      }
      else
      {
        // A bare number is absolute; anything else naming E lacks the h.
        char        *end = nullptr;
        const double v   = std::strtod(compact.c_str(), &end);
        (void)v;
        AssertThrow(*end == '\0' || compact.find('E') == std::string::npos,
                    dealii::ExcMessage(
                      "Parameter <" + entry + "> = <" + text +
                      ">: a multiple of E without the element size depends "
                      "on the length unit (the same model in metres gets a "
                      "penalty 1000 times softer relative to its mesh than "
                      "in millimetres) and is no longer accepted. " +
                      allowed));
      }
      char *end    = nullptr;
      result.value = std::strtod(number.c_str(), &end);
      AssertThrow(!number.empty() && *end == '\0' && result.value > 0 &&
                    std::isfinite(result.value),
                  dealii::ExcMessage("Parameter <" + entry + "> = <" + text +
                                     ">: expected a positive number. " +
                                     allowed));
      AssertThrow(result.value <= Text::largest_value &&
                    result.value >= 1. / Text::largest_value,
                  dealii::ExcMessage(
                    "Parameter <" + entry + "> = <" + text +
                    ">: the number is not of magnitude between 1e-150 and "
                    "1e150 (products of two input values must neither "
                    "overflow nor underflow). " +
                    allowed));
      return result;
    }



    /** The discretization @p text of @p entry. */
    std::string
    parse_discretization(const std::string &text, const std::string &entry)
    {
      AssertThrow(discretization_registry().find(text) != nullptr,
                  dealii::ExcMessage(
                    "Parameter <" + entry + ">: discretization <" + text +
                    "> is unknown. Allowed: " +
                    discretization_registry().join(", ") + "."));
      return text;
    }



    namespace
    {
      /**
       * The discretization of a pair with a rigid master whose default
       * (@p discretization) cannot meet one: the first registered that
       * can (node to segment, which makes its rigid variant).
       */
      std::string
      rigid_master_discretization(const std::string &discretization,
                                  const Contact     &contact)
      {
        if (contact.discretization_method(discretization)
              ->handles_rigid_master())
          return discretization;
        for (const std::string &name : discretization_registry().names())
          if (contact.discretization_method(name)->handles_rigid_master())
            return name;
        AssertThrow(false,
                    dealii::ExcMessage("No registered discretization meets "
                                       "a rigid master surface."));
        return discretization;
      }
    } // namespace



    /** The surfaces of Contact/Rigid surfaces = @p text. */
    std::vector<RigidSurface>
    parse_rigid_surfaces(const std::string &text)
    {
      std::vector<RigidSurface> rigid_surfaces;
      const std::string         rigid_entry = "Contact/Rigid surfaces";
      for (const auto &item : Text::split_top_level(text, ';'))
      {
        const auto parts = Text::split_top_level(item, ':');
        AssertThrow(parts.size() >= 4,
                    dealii::ExcMessage("Parameter <" + rigid_entry +
                                       ">: item <" + item +
                                       "> is incomplete; see the entry's "
                                       "documentation."));
        RigidSurface surface;
        surface.name     = parts[0];
        surface.type     = parts[1];
        surface.point    = Text::parse_doubles(parts[2], rigid_entry);
        std::size_t next = 3;
        if (surface.type == "plane")
          surface.direction = Text::parse_doubles(parts[next++], rigid_entry);
        else if (surface.type == "sphere" || surface.type == "cylinder")
        {
          const auto r = Text::parse_doubles(parts[next++], rigid_entry);
          AssertThrow(r.size() == 1 && r[0] > 0,
                      dealii::ExcMessage("Parameter <" + rigid_entry +
                                         ">: surface <" + surface.name +
                                         "> needs one radius > 0."));
          surface.radius = r[0];
          if (surface.type == "cylinder" && parts.size() == 6)
            surface.direction = Text::parse_doubles(parts[next++], rigid_entry);
        }
        else
          AssertThrow(false,
                      dealii::ExcMessage("Parameter <" + rigid_entry +
                                         ">: surface <" + surface.name +
                                         "> has unknown type <" + surface.type +
                                         ">. Allowed: plane, sphere, "
                                         "cylinder."));
        AssertThrow(next + 1 == parts.size(),
                    dealii::ExcMessage("Parameter <" + rigid_entry +
                                       ">: item <" + item +
                                       "> has the wrong number of ':' "
                                       "fields for a " +
                                       surface.type + "."));
        surface.motion = Text::split_top_level(parts[next], ',');
        AssertThrow(surface.point.size() == 3,
                    dealii::ExcMessage("Parameter <" + rigid_entry +
                                       ">: surface <" + surface.name +
                                       "> needs a point with 3 "
                                       "coordinates (z = 0 in 2D)."));
        rigid_surfaces.push_back(surface);
      }

      return rigid_surfaces;
    }



    /** The pair of Contact/Pairs item @p item, with @p defaults, among
     * the rigid surfaces of @p contact. */
    ContactPair
    parse_pair(const std::string  &item,
               const PairDefaults &defaults,
               const Contact      &contact)
    {
      const std::vector<RigidSurface> &rigid_surfaces = contact.rigid_surfaces;
      const std::string                pair_entry     = "Contact/Pairs";
      const auto                       parts = Text::split_top_level(item, ':');
      AssertThrow(parts.size() == 2 || parts.size() == 3,
                  dealii::ExcMessage("Parameter <" + pair_entry + ">: item <" +
                                     item +
                                     "> must read 'slave : master' or "
                                     "'slave : master : key=value, ...'."));
      for (unsigned int side = 0; side < 2; ++side)
        AssertThrow(!Text::trim(parts[side]).empty(),
                    dealii::ExcMessage(
                      "Parameter <" + pair_entry + ">: item <" + item +
                      "> has no " + (side == 0 ? "slave" : "master") +
                      ": it must read 'slave : master' with a boundary id "
                      "(or list) on each side" +
                      (side == 1 ? " or a rigid surface's name as master." :
                                   ".")));
      ContactPair pair;
      for (const auto id : Text::parse_unsigned(parts[0], pair_entry))
        pair.slave_boundary.insert(id);
      AssertThrow(!pair.slave_boundary.empty(),
                  dealii::ExcMessage("Parameter <" + pair_entry + ">: item <" +
                                     item + "> has no slave boundary id."));
      bool is_rigid = false;
      for (const auto &surface : rigid_surfaces)
        if (surface.name == parts[1])
          is_rigid = true;
      if (is_rigid)
        pair.rigid_surface = parts[1];
      else
      {
        for (const auto &piece : Text::split_top_level(parts[1], ','))
        {
          char      *end = nullptr;
          const long id  = std::strtol(piece.c_str(), &end, 10);
          AssertThrow(!piece.empty() && *end == '\0' && id >= 0,
                      dealii::ExcMessage(
                        "Parameter <" + pair_entry + ">: master <" + parts[1] +
                        "> is neither a list of boundary ids nor the name "
                        "of a surface in <Contact/Rigid surfaces>."));
          pair.master_boundary.insert(id);
        }
        // The same ids on both sides are self-contact; a partial overlap
        // is neither.
        if (pair.master_boundary != pair.slave_boundary)
          for (const auto id : pair.master_boundary)
            AssertThrow(pair.slave_boundary.count(id) == 0,
                        dealii::ExcMessage(
                          "Parameter <" + pair_entry + ">: item <" + item +
                          ">: boundary id " + std::to_string(id) +
                          " is both slave and master. A pair needs "
                          "different slave and master boundaries, or the "
                          "same ones on both sides for self-contact (e.g. <" +
                          parts[0] + " : " + parts[0] + ">)."));
      }
      pair.method               = defaults.method;
      pair.normal_penalty       = defaults.normal_penalty;
      pair.tangential_penalty   = defaults.tangential_penalty;
      pair.friction_coefficient = defaults.friction_coefficient;
      pair.discretization =
        pair.rigid_surface.empty() ?
          defaults.discretization :
          rigid_master_discretization(defaults.discretization, contact);
      bool                  tangential_given = false;
      std::set<std::string> keys;
      if (parts.size() == 3)
        for (const auto &option : Text::split_top_level(parts[2], ','))
        {
          const auto equal = option.find('=');
          AssertThrow(equal != std::string::npos,
                      dealii::ExcMessage("Parameter <" + pair_entry +
                                         ">: option <" + option +
                                         "> must read key=value."));
          const std::string key   = Text::trim(option.substr(0, equal));
          const std::string value = Text::trim(option.substr(equal + 1));
          // 'mu=0.3, mu=0.9': which one was meant is not for tribos to
          // guess.
          AssertThrow(keys.insert(key).second,
                      dealii::ExcMessage("Parameter <" + pair_entry +
                                         ">: item <" + item + ">: option <" +
                                         key +
                                         "> is given twice; give it once."));
          if (key == "method")
          {
            pair.method = parse_method(value, pair_entry);
          }
          else if (key == "penalty")
            pair.normal_penalty = PenaltyValue::parse(value, pair_entry);
          else if (key == "tangential penalty")
          {
            pair.tangential_penalty = PenaltyValue::parse(value, pair_entry);
            tangential_given        = true;
          }
          else if (key == "mu")
          {
            char *end                 = nullptr;
            pair.friction_coefficient = std::strtod(value.c_str(), &end);
            AssertThrow(!value.empty() && *end == '\0' &&
                          pair.friction_coefficient >= 0 &&
                          pair.friction_coefficient <= Text::largest_value,
                        dealii::ExcMessage("Parameter <" + pair_entry +
                                           ">: mu = <" + value +
                                           "> must be a number >= 0."));
          }
          else if (key == "discretization")
          {
            pair.discretization = parse_discretization(value, pair_entry);
            AssertThrow(pair.rigid_surface.empty() ||
                          contact.discretization_method(pair.discretization)
                            ->handles_rigid_master(),
                        dealii::ExcMessage(
                          "Parameter <" + pair_entry + ">: item <" + item +
                          ">: discretization = " + pair.discretization +
                          " needs a deformable master; a rigid surface is "
                          "always met node to surface."));
          }
          else
            AssertThrow(false,
                        dealii::ExcMessage("Parameter <" + pair_entry +
                                           ">: unknown "
                                           "option <" +
                                           key +
                                           ">. Allowed: method, "
                                           "penalty, tangential penalty, mu, "
                                           "discretization."));
        }
      if (!tangential_given && parts.size() == 3 && !defaults.tangential_given)
        pair.tangential_penalty = pair.normal_penalty;
      pair.text = item;
      return pair;
    }



    namespace
    {
      /** The smallest id that the sets @p a and @p b share, if any. */
      std::optional<unsigned int>
      first_shared(const std::set<unsigned int> &a,
                   const std::set<unsigned int> &b)
      {
        for (const auto id : a)
          if (b.count(id) > 0)
            return id;
        return std::nullopt;
      }



      /** Whether the sets @p a and @p b share an id. */
      bool
      meet(const std::set<unsigned int> &a, const std::set<unsigned int> &b)
      {
        return first_shared(a, b).has_value();
      }



      /**
       * One pass of the contact: the nodes of the slave ids checked
       * against the faces of the master ids or a rigid surface. An item of
       * Contact/Pairs is one pass, and with Contact/Passes = two-pass a
       * deformable pair that is not a self pair a second one, slave and
       * master swapped (ContactHandler's descriptions). A self pair is one
       * pass that checks every face of its surface against every other,
       * in both directions at once.
       */
      struct Pass
      {
        unsigned int                  item;
        bool                          second;
        const std::set<unsigned int> *slave;
        const std::set<unsigned int> *master;
      };
    } // namespace



    /**
     * Refuse pairs of @p contact that repeat an interface: an exact
     * duplicate would apply its contact twice; two passes that check the
     * faces of one slave id against those of one master id (or the same
     * rigid surface) apply that contact twice too; the same interface
     * written twice with slave and master swapped, with a method that
     * holds the gap exactly, holds the same gap twice.
     */
    void
    check_interfaces(const Contact &contact)
    {
      const std::vector<ContactPair> &pairs      = contact.pairs;
      const std::string               pair_entry = "Contact/Pairs";
      // The same slave surface against the same master twice: each
      // slave node would carry its contact twice.
      for (unsigned int i = 0; i < pairs.size(); ++i)
        for (unsigned int j = i + 1; j < pairs.size(); ++j)
          AssertThrow(!(pairs[i].slave_boundary == pairs[j].slave_boundary &&
                        pairs[i].master_boundary == pairs[j].master_boundary &&
                        pairs[i].rigid_surface == pairs[j].rigid_surface),
                      dealii::ExcMessage(
                        "Parameter <" + pair_entry + ">: items " +
                        std::to_string(i + 1) + " <" + pairs[i].text +
                        "> and " + std::to_string(j + 1) + " <" +
                        pairs[j].text +
                        "> are the same slave surface against the "
                        "same master: its contact would be "
                        "applied twice. Keep one of them."));

      // Surfaces that only overlap do the same where they overlap: a
      // slave node on the faces of an id that two passes share, checked
      // in both against master faces of an id they share, carries its
      // contact twice (penalty: twice the force, half the penetration the
      // penalty states). A self pair already holds the contact between
      // any two of its ids; two-pass adds the swapped pass of a pair, so
      // that '9 : 10 ; 10 : 9' repeats both directions. A slave node
      // that two passes share only through a corner (slave ids 9 and
      // 11 meeting there) is not refused: each pass gives it the area of
      // its own faces. Nor are two masters for one slave id, or a pair
      // and its own second pass.
      std::vector<Pass> passes;
      for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        passes.push_back(
          {i, false, &pairs[i].slave_boundary, &pairs[i].master_boundary});
        if (contact.two_pass && pairs[i].rigid_surface.empty() &&
            !pairs[i].self_contact())
          passes.push_back(
            {i, true, &pairs[i].master_boundary, &pairs[i].slave_boundary});
      }
      const auto describe = [&pairs](const Pass &pass)
      {
        const ContactPair &pair = pairs[pass.item];
        std::string        text =
          "item " + std::to_string(pass.item + 1) + " <" + pair.text + ">";
        if (pass.second)
          text += "'s second pass (Contact/Passes = two-pass: the pair "
                  "with slave and master swapped)";
        return text;
      };
      for (unsigned int a = 0; a < passes.size(); ++a)
        for (unsigned int b = a + 1; b < passes.size(); ++b)
        {
          const Pass        &p = passes[a], &q = passes[b];
          const ContactPair &first = pairs[p.item], &second = pairs[q.item];
          if (p.item == q.item || !meet(*p.slave, *q.slave))
            continue;
          const bool rigid = !first.rigid_surface.empty();
          if (rigid ?
                first.rigid_surface != second.rigid_surface :
                !second.rigid_surface.empty() || !meet(*p.master, *q.master))
            continue;
          const std::string master =
            rigid ? "the rigid surface " + first.rigid_surface :
                    "master boundary " +
                      std::to_string(*first_shared(*p.master, *q.master));
          AssertThrow(
            false,
            dealii::ExcMessage(
              "Parameter <" + pair_entry + ">: " + describe(p) + " and " +
              describe(q) + " both check slave boundary " +
              std::to_string(*first_shared(*p.slave, *q.slave)) + " against " +
              master +
              ": each slave node there would carry that contact twice "
              "(with penalty twice the force for the same penetration). " +
              (first.self_contact() || second.self_contact() ?
                 "A self-contact pair checks every face of its surface "
                 "against every other, so it holds the contact between "
                 "any two of its boundary ids already. " :
                 "") +
              "Give each slave boundary against each master boundary in "
              "one pair only: drop the id from one of the two pairs, or "
              "the pair."));
        }

      // The same interface written twice with slave and master swapped:
      // with multipliers both sets of node-to-segment constraints hold the
      // same gap (a singular saddle-point system). Penalty may sum both.
      const auto exact = [&contact](const ContactPair &pair)
      {
        return contact.enforcement_method(pair.method)
          ->constrains_gap_exactly();
      };
      // A self pair with a method that holds the gap exactly: both passes
      // would hold each gap twice (a node and the node opposite it, two
      // equal rows), and one pass holds it from one side only, which lets
      // the other side's nodes through. Where the surface's two sides end
      // together (two corners meeting, the U of tests/data/
      // self_contact_u.prm) the one-pass answer is not unique: the U's
      // force at t = 1 was 0.5 % to 20 % above its half model's, depending
      // on the number of steps, and the two-body one-pass pair of the same
      // faces does the same. Penalty (also in mixed form, whose unknowns
      // are each pass's own) and the augmented Lagrangian take both passes
      // with half weights.
      for (const auto &pair : pairs)
        AssertThrow(!(pair.self_contact() && exact(pair)),
                    dealii::ExcMessage(
                      "Parameter <" + pair_entry +
                      ">: the self-contact pair <" + pair.text +
                      "> with method " + pair.method +
                      ": exact constraints can hold each contact from one "
                      "side only, which lets the other side through where "
                      "the surface's two sides end together (the answer "
                      "then depends on the load steps). Use Contact/Method "
                      "= penalty (Penalty formulation = mixed has the "
                      "multipliers' unknowns and solvers) or augmented "
                      "lagrangian: both sides, each with half the "
                      "weight."));
      // Two passes with exact constraints hold each gap twice (a node's
      // row and that of the node opposite it: a singular system). The
      // penalty in mixed form takes them: each pass's traction unknowns
      // have rows g_N + t_N / eps_N = 0 with the compliance on their
      // diagonal, as its self pairs do.
      for (const auto &pair : pairs)
        AssertThrow(!(contact.two_pass && exact(pair)),
                    dealii::ExcMessage(
                      "Contact/Passes = two-pass with Contact/Method = " +
                      pair.method + " (pair <" + pair.text +
                      ">): node-to-segment constraints of both passes "
                      "over-constrain the interface (singular system). Use "
                      "one-pass, or Contact/Method = penalty (Penalty "
                      "formulation = mixed has the multipliers' unknowns "
                      "and solvers)."));
      for (unsigned int i = 0; i < pairs.size(); ++i)
        for (unsigned int j = i + 1; j < pairs.size(); ++j)
          AssertThrow(
            !(pairs[i].rigid_surface.empty() &&
              pairs[j].rigid_surface.empty() &&
              meet(pairs[i].slave_boundary, pairs[j].master_boundary) &&
              meet(pairs[i].master_boundary, pairs[j].slave_boundary) &&
              (exact(pairs[i]) || exact(pairs[j]))),
            dealii::ExcMessage(
              "Parameter <" + pair_entry + ">: pairs <" + pairs[i].text +
              "> and <" + pairs[j].text +
              "> are the same interface with slave and master swapped. "
              "With Lagrange multipliers both sets of constraints hold the "
              "same gap and over-constrain it (singular system): keep one "
              "of them (penalty may use both, like Contact/Passes = "
              "two-pass)."));
    }



  } // namespace Parameters
} // namespace tribos
