#version 150 compatibility
void main() { gl_FragColor = gl_Color; }
