// Lookups in the OpenPBR albedo tables: twins of ggxAlbedoTerms() and sheenAlbedo() in
// core/brdf/openpbr_albedo.cpp. The arrays OPENPBR_GGX_ALBEDO and OPENPBR_SHEEN_ALBEDO come
// generated before this file (openPbrAlbedoGlsl(), through generated/material.glsl).

// Bilinear weights and indices: columns at cos θ_o = (i + ½)/size, rows at r = j/(size − 1).
struct OpenPbrTableCell {
    int i00, i10, i01, i11;
    float fx, fy;
};

OpenPbrTableCell openPbrTableCell(float cosOut, float perceptualRoughness) {
    const int size = OPENPBR_ALBEDO_SIZE;
    float last = float(size - 1);
    float x = clamp(cosOut * float(size) - 0.5, 0.0, last);
    float y = clamp(perceptualRoughness * last, 0.0, last);
    int x0 = int(x), y0 = int(y);
    int x1 = min(x0 + 1, size - 1), y1 = min(y0 + 1, size - 1);
    OpenPbrTableCell cell;
    cell.i00 = y0 * size + x0;
    cell.i10 = y0 * size + x1;
    cell.i01 = y1 * size + x0;
    cell.i11 = y1 * size + x1;
    cell.fx = x - float(x0);
    cell.fy = y - float(y0);
    return cell;
}

vec3 ggxAlbedoTerms(float cosOut, float perceptualRoughness) {
    OpenPbrTableCell c = openPbrTableCell(cosOut, perceptualRoughness);
    vec3 top = OPENPBR_GGX_ALBEDO[c.i00] * (1.0 - c.fx) + OPENPBR_GGX_ALBEDO[c.i10] * c.fx;
    vec3 bottom = OPENPBR_GGX_ALBEDO[c.i01] * (1.0 - c.fx) + OPENPBR_GGX_ALBEDO[c.i11] * c.fx;
    return top * (1.0 - c.fy) + bottom * c.fy;
}

float sheenAlbedo(float cosOut, float perceptualRoughness) {
    OpenPbrTableCell c = openPbrTableCell(cosOut, perceptualRoughness);
    float top = OPENPBR_SHEEN_ALBEDO[c.i00] * (1.0 - c.fx) + OPENPBR_SHEEN_ALBEDO[c.i10] * c.fx;
    float bottom = OPENPBR_SHEEN_ALBEDO[c.i01] * (1.0 - c.fx) + OPENPBR_SHEEN_ALBEDO[c.i11] * c.fx;
    return top * (1.0 - c.fy) + bottom * c.fy;
}
