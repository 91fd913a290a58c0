// Placeholder translation unit until the scene parser lands (replaced by the scene work).
#include "rbd/scene/SceneLoader.h"
