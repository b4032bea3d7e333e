// chNN_demo's entry point: the chapter is the one thing that differs (demo_app.cpp).
#include "demo_app.h"

int main(int argc, char** argv) { return stepwise::render::runDemoApp(STEPWISE_DEMO_CHAPTER, argc, argv); }
