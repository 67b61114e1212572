// featurelines: command-line front end of the FeatureLines core (placeholder; commands follow).
#include <iostream>

int main(int argc, char** argv)
{
    (void)argv;
    std::cerr << "usage: featurelines COMMAND [OPTIONS] INPUT\n";
    return argc > 1 ? 2 : 0;
}
