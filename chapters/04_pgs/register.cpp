// Placeholder while chapter 04 is written; replaced by the chapter's real registration.
#include "app/registry.h"
namespace stepwise {
void registerChapter04(Registry&) {}
}  // namespace stepwise
