#include <iostream>
int main() { std::cout << "mistfall " << MISTFALL_VERSION << "\n"; }
