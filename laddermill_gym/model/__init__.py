"""Model data: typed, frozen parameters of a built system, the state layout, element builders, the kernels'
packed form, and the strict YAML readers. The bottom layer: imports only ``kernels.contract`` of the package."""
