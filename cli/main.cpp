// luxel: render stills, compare shader models, count shader costs, export and describe scenes, bake lightmaps,
// color-correct images, report speed against error (see `luxel --help`).

#include "run.hpp"

int main(int argc, char** argv) { return luxel::cli::run(argc, argv); }
