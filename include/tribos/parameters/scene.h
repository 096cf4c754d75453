#ifndef tribos_parameters_scene_h
#define tribos_parameters_scene_h

#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <string>

namespace tribos
{
  class SceneGeometry;

  namespace Parameters
  {
    /**
     * Subsection `Scene`: which geometry to build and how fine. Each scene
     * declares and reads its own parameters (its subsection of Scene,
     * source/scene/); the one named here is parsed into @p geometry.
     */
    struct Scene
    {
      std::string  name;
      unsigned int refinement;
      /** The scene Name, with its parameters. */
      std::shared_ptr<const SceneGeometry> geometry;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace tribos

#endif
