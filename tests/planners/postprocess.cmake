# tests of smoothing / refinement / comparison with the optimum
