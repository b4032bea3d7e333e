// Placeholder while chapter 03 is written; replaced by the chapter's real registration.
#include "app/registry.h"
namespace stepwise {
void registerChapter03(Registry&) {}
}  // namespace stepwise
