"""Model data: typed, frozen parameters of a built system, the state layout, element builders, the kernels'
packed form, and the strict YAML readers. Imports only ``kernels`` (slot names, the kinds' markers and packers),
``atmosphere`` and the shipped ``configs`` (to find them)."""
