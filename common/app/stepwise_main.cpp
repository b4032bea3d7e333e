// The `stepwise` program: the CLI over every chapter of the course.
#include "app/cli.h"

int main(int argc, char** argv) {
    stepwise::Registry registry;
    stepwise::registerChapters(registry);
    return stepwise::runCli(argc, argv, registry);
}
