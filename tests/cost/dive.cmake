# dive profile tests
