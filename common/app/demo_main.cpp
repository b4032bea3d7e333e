// A chapter's headless demo: the chapter is the one thing that differs (headless_demo.cpp).
#include "app/headless_demo.h"

int main(int argc, char** argv) { return stepwise::runHeadlessDemo(STEPWISE_DEMO_CHAPTER, argc, argv); }
