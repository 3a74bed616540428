/*
 * depth_front_to_back.c - (f) 30 depth-tested layers drawn nearest first.
 * See depth_layers.h.
 */
#define LAYER_ORDER_FRONT_TO_BACK 1
#include "depth_layers.h"
