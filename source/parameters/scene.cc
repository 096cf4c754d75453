#include <tribos/parameters/scene.h>
#include <tribos/scene/scene.h>

namespace tribos
{
  namespace Parameters
  {
    using dealii::ParameterHandler;
    namespace Patterns = dealii::Patterns;



    void
    Scene::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Scene");
      // The scenes that registered themselves (source/scene/).
      prm.declare_entry(
        "Name",
        "block",
        Patterns::Selection(scene_registry().selection_pattern()),
        "The geometry generator. Body (material) and boundary ids of each "
        "are listed in the README.");
      prm.declare_entry("Refinement",
                        "0",
                        Patterns::Integer(0, 10),
                        "Each level doubles every cell count of the scene.");
      scene_registry().declare_parameters(prm);
      prm.leave_subsection();
    }



    void
    Scene::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Scene");
      name       = prm.get("Name");
      refinement = prm.get_integer("Refinement");
      geometry   = parse_scene(name, prm);
      prm.leave_subsection();
    }
  } // namespace Parameters
} // namespace tribos
