# stub, filled later
