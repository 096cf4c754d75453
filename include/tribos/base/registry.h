#ifndef tribos_base_registry_h
#define tribos_base_registry_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace tribos
{
  /**
   * The named plugins of one kind (scenes, enforcement methods,
   * discretizations, materials): each plugin's own source file registers it
   * with a namespace-scope Registration object, so that adding a plugin
   * touches that file only; the parameter file's selection pattern, the
   * lists in messages and the documentation of the choice are generated
   * from the entries, so they cannot miss one (ASPECT's plugin shape, made
   * one template for every kind).
   *
   * A plugin is a default-constructible object of a class derived from
   * @p Base, independent of the dimension: it is made and reads its
   * parameters before the dimension of the run is known, and makes the
   * objects of the run's dimension itself.
   *
   * Registrations run during static initialization, in no defined order
   * between files: the registry of a kind is a function-local static (its
   * accessor is defined once, in the library), add() never throws (a bad
   * entry is recorded and reported by the first lookup, inside main()),
   * and the entries are kept ordered by (rank, name), so that every list
   * the registry gives is the same whatever the order of registration.
   */
  template <class Base>
  class Registry
  {
  public:
    using Declare = void (*)(dealii::ParameterHandler &);
    using Make    = std::unique_ptr<Base> (*)();

    struct Entry
    {
      /** The value that selects the plugin in the parameter file. */
      std::string name;
      /** One phrase for the generated documentation ("" for none). */
      std::string description;
      /**
       * The position in every list: by rank, then by name. The plugins of
       * the first release take 0, 1, 2, ... so that their selection
       * patterns keep their order; a new plugin takes 10 or more.
       */
      int rank = 0;
      /**
       * The position in documentation() if not the rank's: a variant is
       * described next to the plugin it varies (the augmented Lagrangian
       * after the penalty it augments), whereas the selection pattern keeps
       * the order of the first release.
       */
      std::optional<int> documentation_rank;
      /** Declares the plugin's own parameters (null: it has none). */
      Declare declare = nullptr;
      Make    make    = nullptr;
    };

    /** @p kind names the plugins in messages, e.g. "scene". */
    explicit Registry(std::string kind)
      : kind(std::move(kind))
    {
    }

    /**
     * Add @p entry. A name registered twice, empty, with outer blanks or
     * with one of the separators | , ; : = of the parameter syntax is not
     * added but recorded: check() reports it.
     */
    void
    add(Entry entry) noexcept
    {
      const std::string &name = entry.name;
      std::string        problem;
      if (name.empty() || name.front() == ' ' || name.back() == ' ' ||
          name.find_first_of("|,;:=") != std::string::npos)
        problem = "the name <" + name +
                  "> is empty, has outer blanks or one of | , ; : =";
      else if (entry.make == nullptr)
        problem = "<" + name + "> has no factory";
      else if (find_entry(name) != nullptr)
        problem = "<" + name + "> is registered twice";
      if (!problem.empty())
      {
        problems.push_back(problem);
        return;
      }
      const auto position =
        std::upper_bound(entries.begin(),
                         entries.end(),
                         entry,
                         [](const Entry &a, const Entry &b) {
                           return std::tie(a.rank, a.name) <
                                  std::tie(b.rank, b.name);
                         });
      entries.insert(position, std::move(entry));
    }

    /** Throw if a registration was refused (a programming error, reported
     * inside main() rather than during static initialization). */
    void
    check() const
    {
      AssertThrow(problems.empty(),
                  dealii::ExcMessage("The " + kind +
                                     " registry: " + problems.front() + "."));
    }

    /** The entry called @p name, null if none is. */
    const Entry *
    find(const std::string &name) const
    {
      check();
      return find_entry(name);
    }

    /**
     * A new plugin called @p name, its name set; null if none is, so that
     * the caller says which parameter gave the name.
     */
    std::unique_ptr<Base>
    create(const std::string &name) const
    {
      const Entry *entry = find(name);
      if (entry == nullptr)
        return nullptr;
      std::unique_ptr<Base> plugin = entry->make();
      plugin->name                 = name;
      return plugin;
    }

    /** The names, by rank and then name. */
    std::vector<std::string>
    names() const
    {
      check();
      std::vector<std::string> result;
      for (const Entry &entry : entries)
        result.push_back(entry.name);
      return result;
    }

    /** The names joined by @p separator, each in @p quote. */
    std::string
    join(const std::string &separator, const std::string &quote = "") const
    {
      std::string result;
      for (const std::string &name : names())
        result += (result.empty() ? "" : separator) + quote + name + quote;
      return result;
    }

    /** deal.II's Patterns::Selection of the names ("a|b|c"). */
    std::string
    selection_pattern() const
    {
      return join("|");
    }

    /**
     * "<q>a<q>: description of a; <q>b<q>: ..." by documentation rank (the
     * rank unless given), rank and name (the entries without a description
     * give their name alone).
     */
    std::string
    documentation(const std::string &quote = "") const
    {
      check();
      std::vector<const Entry *> ordered;
      for (const Entry &entry : entries)
        ordered.push_back(&entry);
      // Stable: equal documentation ranks keep the order of rank and name.
      std::stable_sort(ordered.begin(),
                       ordered.end(),
                       [](const Entry *a, const Entry *b)
                       {
                         return a->documentation_rank.value_or(a->rank) <
                                b->documentation_rank.value_or(b->rank);
                       });
      std::string result;
      for (const Entry *entry : ordered)
        result += (result.empty() ? "" : "; ") + quote + entry->name + quote +
                  (entry->description.empty() ? "" : ": " + entry->description);
      return result;
    }

    /**
     * Every plugin's declare(), by rank and name: all of them, since the
     * choice is read from the same file (deal.II's ParameterHandler needs
     * every entry declared before it parses).
     */
    void
    declare_parameters(dealii::ParameterHandler &prm) const
    {
      check();
      for (const Entry &entry : entries)
        if (entry.declare != nullptr)
          entry.declare(prm);
    }

    /**
     * Every plugin, made and its parameters read from @p prm (where
     * declare_parameters() declared them) by its parse_parameters(), by
     * rank and name: a parameter file may select any of them in several
     * places (a contact pair's own method=, a body's model), and every
     * plugin's entries are checked whatever is selected, as a mistyped
     * entry should fail whether or not it is used.
     */
    std::map<std::string, std::shared_ptr<const Base>>
    parse_all(dealii::ParameterHandler &prm) const
    {
      check();
      std::map<std::string, std::shared_ptr<const Base>> plugins;
      for (const Entry &entry : entries)
      {
        std::unique_ptr<Base> plugin = create(entry.name);
        plugin->parse_parameters(prm);
        plugins[entry.name] = std::move(plugin);
      }
      return plugins;
    }

    /**
     * The plugin called @p name with its parameters at their declared
     * defaults (null if none is called so): for parameter structs that a
     * benchmark or test fills by hand, which parse_all() never saw.
     */
    std::shared_ptr<const Base>
    create_with_defaults(const std::string &name) const
    {
      const Entry *entry = find(name);
      if (entry == nullptr)
        return nullptr;
      dealii::ParameterHandler prm;
      if (entry->declare != nullptr)
        entry->declare(prm);
      std::unique_ptr<Base> plugin = create(name);
      plugin->parse_parameters(prm);
      return plugin;
    }

    /** The object a plugin file defines (static) to register itself. */
    struct Registration
    {
      Registration(Registry &registry, Entry entry)
      {
        registry.add(std::move(entry));
      }
    };

  private:
    const Entry *
    find_entry(const std::string &name) const
    {
      for (const Entry &entry : entries)
        if (entry.name == name)
          return &entry;
      return nullptr;
    }

    std::string              kind;
    std::vector<Entry>       entries;
    std::vector<std::string> problems;
  };



  namespace internal
  {
    /** Whether @p Plugin has a static declare_parameters(ParameterHandler &).
     */
    template <class Plugin, class = void>
    struct HasDeclareParameters : std::false_type
    {
    };

    template <class Plugin>
    struct HasDeclareParameters<Plugin,
                                std::void_t<decltype(Plugin::declare_parameters(
                                  std::declval<dealii::ParameterHandler &>()))>>
      : std::true_type
    {
    };
  } // namespace internal



  /**
   * The registration of @p Plugin (default constructible, derived from
   * @p Base; its static declare_parameters(prm) is used if it has one) in
   * @p registry under @p name (Entry explains @p description, @p rank and
   * @p documentation_rank).
   */
  template <class Plugin, class Base>
  typename Registry<Base>::Registration
  register_plugin(Registry<Base>          &registry,
                  const std::string       &name,
                  const std::string       &description        = "",
                  const int                rank               = 0,
                  const std::optional<int> documentation_rank = {})
  {
    typename Registry<Base>::Entry entry;
    entry.name               = name;
    entry.description        = description;
    entry.rank               = rank;
    entry.documentation_rank = documentation_rank;
    if constexpr (internal::HasDeclareParameters<Plugin>::value)
      entry.declare = &Plugin::declare_parameters;
    entry.make = []() -> std::unique_ptr<Base>
    {
      return std::make_unique<Plugin>();
    };
    return typename Registry<Base>::Registration(registry, std::move(entry));
  }
} // namespace tribos

#endif
