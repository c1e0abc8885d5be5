hand-written: an incremental program of two steps (gringo writes these only from multi-shot solving)
