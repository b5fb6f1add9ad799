#version 430 core
// Lab 5: spacing=fractional_odd. The spacing is a layout qualifier, fixed when
// the program is linked, so the lab links one program per spacing, each
// with this one-line shader object next to the scene's evaluation shader:
// the layout of a stage may be declared in any of its shader objects.
layout(fractional_odd_spacing) in;
