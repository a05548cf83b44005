"""A diagram with shapes and no text: the book build must reject it."""
print('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 40" width="100" height="40">'
      '<rect x="5" y="5" width="40" height="30" fill="none" stroke="black"/>'
      '<rect x="55" y="5" width="40" height="30" fill="none" stroke="black"/></svg>')
