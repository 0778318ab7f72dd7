package dolphin.sim;

/**
 * A parameter a simulated firmware answers PARAM_REQUEST_READ with: its name, its value under SITL's
 * default parameters, and its MAV_PARAM_TYPE, which follows the AP_Param type ArduPilot declares it
 * with (GCS_MAVLINK::mav_param_type: AP_Int8 is INT8, AP_Float REAL32).
 */
record FirmwareParam(String name, float value, int type) {
}
