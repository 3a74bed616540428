/*
 * depth_back_to_front.c - (f) 30 depth-tested layers drawn farthest first.
 * See depth_layers.h.
 */
#define LAYER_ORDER_FRONT_TO_BACK 0
#include "depth_layers.h"
