// ctest: labels quick
/**
 * The plugin registry (include/tribos/base/registry.h): order by rank and
 * name whatever the order of registration, refused names reported by the
 * first lookup (not during static initialization), the generated selection
 * pattern and documentation (in an order of its own where asked),
 * create() naming its plugin, parse_all() and create_with_defaults()
 * reading the plugins' entries; and the registries
 * of the library: every scene file registered, the enforcement methods,
 * discretizations and material models of the first release first and in
 * its order (the first is the default; a plugin added later ranks after
 * them, so that adding one is one new file and its own test),
 * every plugin reading its own defaults, and
 * no two plugins of a kind declaring the same parameter (deal.II's
 * ParameterHandler would silently keep the later declaration).
 */

#include <tribos/base/registry.h>
#include <tribos/contact/discretization/discretization_method.h>
#include <tribos/contact/enforcement/enforcement_method.h>
#include <tribos/material/material_model.h>
#include <tribos/scene/scene.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <iostream>
#include <set>
#include <sstream>
#include <string>

using namespace dealii;

namespace
{
  unsigned int n_failed = 0;

  void
  check(const bool condition, const std::string &message)
  {
    std::cout << (condition ? "ok      " : "FAILED  ") << message << '\n';
    if (!condition)
      ++n_failed;
  }

  struct Plugin
  {
    virtual ~Plugin() = default;

    virtual void
    parse_parameters(ParameterHandler &)
    {
    }

    virtual int
    value() const = 0;

    std::string name;
  };

  struct One : Plugin
  {
    int
    value() const override
    {
      return 1;
    }
  };

  struct Two : Plugin
  {
    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Two's entry", "2", Patterns::Integer());
    }

    void
    parse_parameters(ParameterHandler &prm) override
    {
      entry = prm.get_integer("Two's entry");
    }

    int
    value() const override
    {
      return 2;
    }

    /** Two's entry, as read. */
    int entry = 0;
  };

  /** The paths of every entry @p prm declares ("a/b/c"), from its JSON
   * print-out. */
  std::set<std::string>
  entry_paths(const ParameterHandler &prm)
  {
    std::ostringstream text;
    prm.print_parameters(text, ParameterHandler::ShortPRM);
    std::set<std::string>    paths;
    std::vector<std::string> sections;
    std::string              line;
    std::istringstream       lines(text.str());
    while (std::getline(lines, line))
    {
      const auto first = line.find_first_not_of(' ');
      if (first == std::string::npos)
        continue;
      line = line.substr(first);
      if (line.rfind("subsection ", 0) == 0)
        sections.push_back(line.substr(11));
      else if (line == "end")
        sections.pop_back();
      else if (line.rfind("set ", 0) == 0)
      {
        std::string path;
        for (const auto &s : sections)
          path += s + "/";
        const auto  equals = line.find('=');
        std::string name   = line.substr(4, equals - 4);
        name.erase(name.find_last_not_of(' ') + 1);
        paths.insert(path + name);
      }
    }
    return paths;
  }



  /** Whether the plugins of @p registry (of the @p kind) declare distinct
   * entries: each alone, then all together. */
  /** Whether the selection pattern @p pattern lists the choices @p first
   * (separated by '|') first, followed by nothing or by more choices. */
  bool
  starts_with_choices(const std::string &pattern, const std::string &first)
  {
    return pattern.compare(0, first.size(), first) == 0 &&
           (pattern.size() == first.size() || pattern[first.size()] == '|');
  }



  template <class Base>
  void
  check_distinct_entries(const tribos::Registry<Base> &registry,
                         const std::string            &kind)
  {
    std::size_t n_entries = 0;
    for (const std::string &name : registry.names())
    {
      ParameterHandler alone;
      if (const auto declare = registry.find(name)->declare)
        declare(alone);
      n_entries += entry_paths(alone).size();
    }
    ParameterHandler together;
    registry.declare_parameters(together);
    check(entry_paths(together).size() == n_entries,
          "the " + kind + "' " + std::to_string(n_entries) +
            " entries are distinct");
  }



  /** Whether every plugin of @p registry reads the defaults of its own
   * entries. */
  template <class Base>
  void
  check_defaults(const tribos::Registry<Base> &registry)
  {
    for (const std::string &name : registry.names())
    {
      bool made = false;
      try
      {
        const auto plugin = registry.create_with_defaults(name);
        made              = plugin != nullptr && plugin->name == name;
      }
      catch (const std::exception &e)
      {
        std::cout << e.what() << '\n';
      }
      check(made, "<" + name + "> reads its defaults");
    }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using tribos::Registry;

  // Registered out of order: lists by rank, then name.
  Registry<Plugin> registry("test plugin");
  tribos::register_plugin<Two>(registry, "two", "the second", 1);
  tribos::register_plugin<One>(registry, "one", "the first", 0);
  tribos::register_plugin<One>(registry, "also one", "", 0);
  check(registry.selection_pattern() == "also one|one|two",
        "selection pattern by rank, then name: " +
          registry.selection_pattern());
  check(registry.documentation("'") ==
          "'also one'; 'one': the first; 'two': the second",
        "documentation: " + registry.documentation("'"));
  check(registry.join(", ") == "also one, one, two", "join");

  const auto two = registry.create("two");
  check(two != nullptr && two->value() == 2 && two->name == "two",
        "create() makes the plugin and names it");
  check(registry.create("three") == nullptr,
        "create() of an unknown name is null (the caller names the "
        "parameter)");

  ParameterHandler prm;
  registry.declare_parameters(prm);
  check(entry_paths(prm) == std::set<std::string>{"Two's entry"},
        "declare_parameters() declares the plugins' own entries only");

  prm.set("Two's entry", "5");
  const auto  all        = registry.parse_all(prm);
  const auto *parsed_two = dynamic_cast<const Two *>(all.at("two").get());
  check(all.size() == 3 && parsed_two != nullptr && parsed_two->entry == 5,
        "parse_all() makes every plugin, which reads its entries");
  const auto  with_defaults = registry.create_with_defaults("two");
  const auto *default_two   = dynamic_cast<const Two *>(with_defaults.get());
  check(default_two != nullptr && default_two->entry == 2 &&
          default_two->name == "two",
        "create_with_defaults() reads the declared defaults");
  check(registry.create_with_defaults("three") == nullptr,
        "create_with_defaults() of an unknown name is null");

  // A documentation rank describes a plugin out of the pattern's order.
  Registry<Plugin> ordered("test plugin");
  tribos::register_plugin<One>(ordered, "a", "first", 0);
  tribos::register_plugin<One>(ordered, "b", "described last", 1, 2);
  tribos::register_plugin<One>(ordered, "c", "described second", 2, 1);
  check(ordered.selection_pattern() == "a|b|c" &&
          ordered.documentation() ==
            "a: first; c: described second; b: described last",
        "documentation rank: " + ordered.documentation());

  // Refused registrations: recorded, then thrown by the first lookup.
  for (const std::string bad : {"two", "a|b", "a : b", " padded", ""})
  {
    Registry<Plugin> other("test plugin");
    tribos::register_plugin<Two>(other, "two", "", 0);
    tribos::register_plugin<One>(other, bad, "", 0);
    bool thrown = false;
    try
    {
      other.names();
    }
    catch (const std::exception &e)
    {
      thrown =
        std::string(e.what()).find("test plugin registry") != std::string::npos;
    }
    check(thrown, "the name <" + bad + "> is refused at the first lookup");
  }

  // The library's scenes.
  const auto                  scenes = tribos::scene_registry().names();
  const std::set<std::string> names(scenes.begin(), scenes.end());
  for (const std::string scene : {"block",
                                  "cylinder compression",
                                  "cylinder over block",
                                  "gmsh",
                                  "ring on foundation",
                                  "two blocks"})
    check(names.count(scene) == 1, "scene <" + scene + "> is registered");

  check_distinct_entries(tribos::scene_registry(), "scenes");

  // The enforcement methods: the first release's Contact/Method choices
  // first, in their order.
  const auto &methods = tribos::enforcement_registry();
  check(starts_with_choices(methods.selection_pattern(),
                            "penalty|lagrange multiplier|augmented lagrangian"),
        "enforcement methods: " + methods.selection_pattern());
  check_defaults(methods);
  check_distinct_entries(methods, "enforcement methods");

  // The discretizations: the first release's Contact/Discretization
  // choices first.
  const auto &discretizations = tribos::discretization_registry();
  check(starts_with_choices(discretizations.selection_pattern(),
                            "node to segment|mortar"),
        "discretizations: " + discretizations.selection_pattern());
  check_defaults(discretizations);
  check_distinct_entries(discretizations, "discretizations");

  // The material models: the first release's Materials/Model choices
  // first.
  const auto &models = tribos::material_registry();
  check(starts_with_choices(models.selection_pattern(),
                            "linear elastic|neo-Hookean|J2 plasticity"),
        "material models: " + models.selection_pattern());
  check_defaults(models);
  check_distinct_entries(models, "material models");

  std::cout << (n_failed == 0 ? "all passed" : "FAILED") << '\n';
  return n_failed == 0 ? 0 : 1;
}
