"""The 3-D picture editor for cell types (thesis section 8.1), a program on the Rainbow:
draw a cell type's lathe profile in one pad, watch the lathed solid turn in another, set its
colour and material, save the rule set's actors file."""
