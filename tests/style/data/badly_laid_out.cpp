// Laid out against .clang-format on purpose: scripts/format.sh --check must name this file.
int  twice( int x ){return 2*x;}
