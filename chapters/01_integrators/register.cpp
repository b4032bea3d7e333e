// Placeholder while chapter 01 is written; replaced by the chapter's real registration.
#include "app/registry.h"
namespace stepwise {
void registerChapter01(Registry&) {}
}  // namespace stepwise
