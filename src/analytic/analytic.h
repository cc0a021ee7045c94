#pragma once

/**
 * @file
 * @brief Everything the closed-form multiple sliding block model offers
 * (chapter 6): include this one header to use the module.
 */

#include <analytic/block_chain.h>
#include <analytic/centroid_heights.h>
#include <analytic/corner_contact.h>
#include <analytic/floor_shape.h>
#include <analytic/hertz.h>
#include <analytic/rotation_no_vertical_slip.h>
#include <analytic/rotation_vertical_slip.h>
#include <analytic/slip_no_rotation.h>
#include <analytic/status.h>
