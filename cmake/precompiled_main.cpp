// The programs' header images are made with this translation unit (precompiled.cmake).
int main() { return 0; }
