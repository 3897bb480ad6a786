// Shadow-map depth pass: depth only (the rasteriser writes it; glPolygonOffset adds the slope term).
void main() {}
