// Placeholder while chapter 02 is written; replaced by the chapter's real registration.
#include "app/registry.h"
namespace stepwise {
void registerChapter02(Registry&) {}
}  // namespace stepwise
