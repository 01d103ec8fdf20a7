#include "a[31mbÿÃ©.inc"
camera { location <0, 1, -5> look_at 0 }
